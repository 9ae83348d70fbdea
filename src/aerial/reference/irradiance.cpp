#include "aerial/reference/irradiance.h"

#include <numbers>

#include "aerial/reference/multiple_scattering.h"
#include "aerial/reference/optical_depth.h"
#include "aerial/reference/path_tracer.h"
#include "aerial/reference/solar_disc.h"

namespace aerial::reference {

Spectrum ComputeDirectIrradiance(const Medium& medium, Accuracy accuracy, double r, double mu_s) {
  const AtmosphereParameters& a = medium.atmosphere();
  Spectrum f = SunDiscHorizontalIrradianceFactor(medium, accuracy, r, mu_s);
  return {a.solar_irradiance[0] * f[0], a.solar_irradiance[1] * f[1], a.solar_irradiance[2] * f[2]};
}

Channels SampleDirectIrradiance(const WavelengthGroups& groups, double r, double mu_s, Rng& rng) {
  Channels e = SampleSunDiscHorizontalIrradianceFactor(groups, r, mu_s, rng);
  for (int c = 0; c < e.size(); ++c) e[c] *= groups.SolarIrradiance(c);
  return e;
}

GroupOrderEstimates EstimateSkyIrradianceOrders(const WavelengthGroups& groups, double r, double mu_s,
                                                double mu_n, double nu_n, int max_order,
                                                        const MonteCarloOptions& options) {
  // The normal stands where a view direction would: at (0, 0, r), in the xz plane, the sun placed
  // at nu_n from it (for a horizontal surface: the normal up, the sun in the xz plane).
  const ViewFrame frame = MakeViewFrame(r, mu_n, mu_s, nu_n);
  const Vec3 x = frame.camera, normal = frame.view;
  return RunChunks(options, max_order, groups.channels(), [&](int, Rng& rng, std::vector<Channels>& sums) {
    PathTracer tracer(groups, frame.sun, 1, max_order, options.roulette_from_order);
    Strata strata(rng);
    for (int i = 0; i < kChunkPaths; ++i) {
      // E = int L cos dw, estimated as L(w) cos(w) / pdf(w) = pi L(w) (cos / pi) / pdf(w).
      Vec3 w;
      double cos_over_pdf = tracer.SampleSurfaceDirection(normal, rng.Uniform(), strata.Sample2D(i, rng), &w);
      double u_choice = rng.Uniform(), u_distance = strata.Sample1D(i, rng);
      if (!(cos_over_pdf > 0.0)) continue;
      PathVertex v;
      Channels beta;
      if (!tracer.SampleSegment(x, w, u_choice, u_distance, &v, &beta)) continue;
      for (int c = 0; c < beta.size(); ++c) beta[c] *= std::numbers::pi * cos_over_pdf;
      tracer.Continue(v, beta, 1, rng, nullptr, sums);
    }
  });
}

OrderEstimates EstimateSkyIrradianceOrders(const Medium& medium, double r, double mu_s, double mu_n,
                                           double nu_n, int max_order, const MonteCarloOptions& options) {
  return EstimateSkyIrradianceOrders(WavelengthGroups(medium.atmosphere()), r, mu_s, mu_n, nu_n, max_order,
                                     options).groups[0];
}

}  // namespace aerial::reference
