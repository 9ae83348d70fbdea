#include "aerial/reference/multiple_scattering.h"

#include "aerial/reference/distance_sampler.h"
#include "aerial/reference/geometry.h"
#include "aerial/reference/optical_depth.h"
#include "aerial/reference/path_tracer.h"

namespace aerial::reference {

double ClampNu(double mu, double mu_s, double nu) {
  double spread = SafeSqrt((1.0 - mu * mu) * (1.0 - mu_s * mu_s));
  return std::clamp(nu, mu * mu_s - spread, mu * mu_s + spread);
}

ViewFrame MakeViewFrame(double r, double mu, double mu_s, double nu) {
  double sin_view = SafeSqrt(1.0 - mu * mu), sin_sun = SafeSqrt(1.0 - mu_s * mu_s);
  // view . sun = sin_view sun_x + mu mu_s = nu.
  double sun_x = sin_view > 0.0 ? std::clamp((nu - mu * mu_s) / sin_view, -sin_sun, sin_sun) : sin_sun;
  double sun_y = SafeSqrt(1.0 - mu_s * mu_s - sun_x * sun_x);
  return {{0.0, 0.0, r}, {sin_view, 0.0, mu}, {sun_x, sun_y, mu_s}};
}

GroupOrderEstimates EstimateRadianceOrders(const WavelengthGroups& groups, double r, double mu, double mu_s,
                                           double nu, double length, int first_order, int max_order,
                                                   const MonteCarloOptions& options) {
  const Medium& medium = groups.sampling();
  const ViewFrame frame = MakeViewFrame(r, mu, mu_s, nu);
  RayColumns view;
  view.Build(medium, Accuracy::kMonteCarlo, r, mu, length);
  DistanceSampler first_vertex;
  first_vertex.Build(medium, view);
  return RunChunks(options, max_order, groups.channels(), [&](int, Rng& rng, std::vector<Channels>& sums) {
    if (!(length > 0.0)) return;
    PathTracer tracer(groups, frame.sun, first_order, max_order, options.roulette_from_order);
    Strata strata(rng);
    for (int i = 0; i < kChunkPaths; ++i) {
      double pdf;
      double s = first_vertex.Sample(strata.Sample1D(i, rng), &pdf);
      std::array<double, 2> u = strata.Sample2D(i, rng);
      if (!(pdf > 0.0)) continue;
      Channels beta = groups.Transmittance(view.ColumnTo(s));
      for (int c = 0; c < beta.size(); ++c) beta[c] /= pdf;
      tracer.Continue({frame.camera + s * frame.view, frame.view, false}, beta, 1, rng, &u, sums);
    }
  });
}

OrderEstimates EstimateRadianceOrders(const Medium& medium, double r, double mu, double mu_s, double nu,
                                      double length, int first_order, int max_order,
                                      const MonteCarloOptions& options) {
  return EstimateRadianceOrders(WavelengthGroups(medium.atmosphere()), r, mu, mu_s, nu, length, first_order,
                                max_order, options).groups[0];
}

}  // namespace aerial::reference
