#include "aerial/reference/path_tracer.h"

#include <numbers>

#include "aerial/reference/geometry.h"
#include "aerial/reference/irradiance.h"
#include "aerial/reference/phase_functions.h"
#include "aerial/reference/solar_disc.h"

namespace aerial::reference {
namespace {

constexpr double kPi = std::numbers::pi;

double Mean(const Spectrum& s) { return (s[0] + s[1] + s[2]) / 3.0; }

}  // namespace

PathTracer::PathTracer(const WavelengthGroups& groups, Vec3 sun, int first_order, int max_order,
                       int roulette_from_order)
    : groups_(groups),
      medium_(groups.sampling()),
      sun_(sun),
      first_order_(first_order),
      max_order_(max_order),
      roulette_from_order_(roulette_from_order) {
  // The sun lobe pays off only where the Mie forward peak is sharp; 20% keeps the phase lobes'
  // weights within 1.25x of pure phase sampling.
  const AtmosphereParameters& a = medium_.atmosphere();
  sun_lobe_ = Mean(a.mie_scattering) > 0.0 && a.mie_phase_g > 0.3 ? 0.2 : 0.0;
}

double PathTracer::BounceEnergy(const PathVertex& v, const Densities& d, const Channels& f,
                                const PathVertex& next, const Channels& weight) const {
  const int n = groups_.channels();
  auto extinction = [&](const Densities& at) {
    return groups_.OpticalDepth(Column{at.rayleigh, at.mie, at.absorption});  // per meter
  };
  Channels from = v.ground ? Channels(n, 1.0) : extinction(d);
  Channels to = next.ground ? Channels(n, 1.0) : extinction(medium_.At(Length(next.p) - medium_.bottom_radius()));
  double energy = 0.0;
  for (int c = 0; c < n; ++c)
    if (from[c] > 0.0) energy = std::max(energy, f[c] / from[c] * weight[c] * to[c]);
  return energy;
}

Channels PathTracer::AtmosphereNextEvent(const PathVertex& v, const Densities& d, Rng& rng) const {
  double r = Length(v.p);
  double mu_s = ClampCosine(Dot(v.p, sun_) / r);
  Channels out = SampleSunDiscTransmittance(groups_, r, mu_s, rng);
  if (!(out.Max() > 0.0)) return out;
  double nu = ClampCosine(Dot(v.w_in, sun_));
  double phase_r = RayleighPhaseFunction(nu),
         phase_m = CornetteShanksPhaseFunction(medium_.atmosphere().mie_phase_g, nu);
  for (int c = 0; c < out.size(); ++c) {
    out[c] *= (groups_.RayleighScattering(c) * d.rayleigh * phase_r + groups_.MieScattering(c) * d.mie * phase_m) *
              groups_.SolarIrradiance(c);
  }
  return out;
}

Channels PathTracer::GroundNextEvent(const PathVertex& v, Rng& rng) const {
  double r = Length(v.p);
  Channels e = SampleDirectIrradiance(groups_, r, ClampCosine(Dot(v.p, sun_) / r), rng);
  for (int c = 0; c < e.size(); ++c) e[c] *= groups_.GroundAlbedo(c) / kPi;
  return e;
}

Channels PathTracer::SampleAtmosphereDirection(const PathVertex& v, const Densities& d, double u_lobe,
                                               std::array<double, 2> u, Vec3* w) const {
  const AtmosphereParameters& a = medium_.atmosphere();
  const double g = a.mie_phase_g;
  // Rayleigh lobe probability: the channels' Rayleigh fractions of beta_s, averaged (spectral
  // MIS), so each channel's weight is at most 3x that of its own mixture.
  double p_rayleigh = 0.0;
  for (int c = 0; c < 3; ++c) {
    double sigma_r = a.rayleigh_scattering[c] * d.rayleigh, sigma_m = a.mie_scattering[c] * d.mie;
    p_rayleigh += (sigma_r + sigma_m > 0.0 ? sigma_r / (sigma_r + sigma_m) : 1.0) / 3.0;
  }
  double phi = 2.0 * kPi * u[1];
  if (u_lobe < sun_lobe_) {
    *w = AroundAxis(sun_, SampleHenyeyGreensteinCosine(g, u[0]), phi);
  } else if ((u_lobe - sun_lobe_) / (1.0 - sun_lobe_) < p_rayleigh) {
    *w = AroundAxis(v.w_in, SampleRayleighCosine(u[0]), phi);
  } else {
    *w = AroundAxis(v.w_in, SampleHenyeyGreensteinCosine(g, u[0]), phi);
  }
  double nu = ClampCosine(Dot(v.w_in, *w));
  double pdf = sun_lobe_ * HenyeyGreensteinPhaseFunction(g, ClampCosine(Dot(sun_, *w))) +
               (1.0 - sun_lobe_) * (p_rayleigh * RayleighPhaseFunction(nu) +
                                    (1.0 - p_rayleigh) * HenyeyGreensteinPhaseFunction(g, nu));
  double phase_r = RayleighPhaseFunction(nu), phase_m = CornetteShanksPhaseFunction(g, nu);
  Channels out(groups_.channels());
  for (int c = 0; c < out.size(); ++c)
    out[c] = (groups_.RayleighScattering(c) * d.rayleigh * phase_r + groups_.MieScattering(c) * d.mie * phase_m) / pdf;
  return out;
}

double PathTracer::SampleSurfaceDirection(Vec3 normal, double u_lobe, std::array<double, 2> u,
                                            Vec3* w) const {
  const double g = medium_.atmosphere().mie_phase_g;
  double phi = 2.0 * kPi * u[1];
  // Cosine-weighted hemisphere: cos(theta) = sqrt(u) has density cos / pi per steradian.
  *w = u_lobe < sun_lobe_ ? AroundAxis(sun_, SampleHenyeyGreensteinCosine(g, u[0]), phi)
                          : AroundAxis(normal, std::sqrt(u[0]), phi);
  double cos_theta = Dot(normal, *w);
  if (!(cos_theta > 0.0)) return 0.0;
  double pdf = sun_lobe_ * HenyeyGreensteinPhaseFunction(g, ClampCosine(Dot(sun_, *w))) +
               (1.0 - sun_lobe_) * cos_theta / kPi;
  return cos_theta / kPi / pdf;
}

bool PathTracer::SampleSegment(Vec3 p, Vec3 w, double u_choice, double u_distance, PathVertex* next,
                               Channels* weight) {
  const double bottom = medium_.bottom_radius();
  double r = Length(p);
  double mu = ClampCosine(Dot(p, w) / r);
  bool ground = RayIntersectsInnerSphere(r, mu, bottom);
  double length = ground ? DistanceToInnerSphere(r, mu, bottom)
                         : DistanceToOuterSphere(r, mu, medium_.top_radius());
  if (!(length > 0.0)) {
    // On the ground and going down (a tilted surface's hemisphere there): the ground at once,
    // through no air, with probability 1.
    if (!ground) return false;
    *next = {(bottom / r) * p, w, true};
    *weight = Channels(groups_.channels(), 1.0);
    return true;
  }
  columns_.Build(medium_, Accuracy::kMonteCarlo, r, mu, length);
  // Ground vs atmosphere, in proportion to rough estimates of what each returns: the ground
  // ~ T albedo E_sun / (4 pi) x 10 (direct plus sky irradiance ~ E_sun / 2, reflected / pi)
  // against the segment's in-scattering ~ (1 - T) E_sun / (4 pi).
  double p_ground = 0.0;
  double albedo = Mean(medium_.atmosphere().ground_albedo);
  if (ground && albedo > 0.0) {
    double t = std::exp(-medium_.MeanOpticalDepth(columns_.cumulative().back()));
    p_ground = std::clamp(2.5 * albedo * t / (2.5 * albedo * t + 1.0 - t), 0.05, 0.95);
  }
  if (u_choice < p_ground) {
    Vec3 q = p + length * w;
    *next = {(bottom / Length(q)) * q, w, true};
    *weight = groups_.Transmittance(columns_.cumulative().back());
    for (int c = 0; c < weight->size(); ++c) (*weight)[c] /= p_ground;
    return true;
  }
  distances_.Build(medium_, columns_);
  double pdf;
  double s = distances_.Sample(u_distance, &pdf);
  if (!(pdf > 0.0)) return false;
  *weight = groups_.Transmittance(columns_.ColumnTo(s));
  for (int c = 0; c < weight->size(); ++c) (*weight)[c] /= pdf * (1.0 - p_ground);
  *next = {p + s * w, w, false};
  return true;
}

void PathTracer::Continue(PathVertex v, Channels beta, int order, Rng& rng,
                          const std::array<double, 2>* first_u, std::vector<Channels>& sums) {
  const int n = groups_.channels();
  while (true) {
    Densities d;
    if (!v.ground) d = medium_.At(Length(v.p) - medium_.bottom_radius());
    if (order >= first_order_) {
      Channels e = v.ground ? GroundNextEvent(v, rng) : AtmosphereNextEvent(v, d, rng);
      Channels& sum = sums[std::min<size_t>(order, sums.size() - 1)];
      for (int c = 0; c < n; ++c) sum[c] += beta[c] * e[c];
    }
    if (order >= max_order_ || order >= kMaxPathVertices) return;
    std::array<double, 2> u = first_u ? *first_u : std::array<double, 2>{rng.Uniform(), rng.Uniform()};
    first_u = nullptr;
    double u_lobe = rng.Uniform();
    Vec3 w;
    Channels f(n);
    if (v.ground) {
      const double cos_over_pdf = SampleSurfaceDirection(Normalize(v.p), u_lobe, u, &w);
      // Lambertian BRDF albedo / pi, times cos.
      for (int c = 0; c < n; ++c) f[c] = cos_over_pdf * groups_.GroundAlbedo(c);
    } else {
      f = SampleAtmosphereDirection(v, d, u_lobe, u, &w);
    }
    for (int c = 0; c < n; ++c) beta[c] *= f[c];
    if (!(beta.Max() > 0.0)) return;
    PathVertex next;
    Channels weight;
    double u_choice = rng.Uniform(), u_distance = rng.Uniform();
    if (!SampleSegment(v.p, w, u_choice, u_distance, &next, &weight)) return;
    for (int c = 0; c < n; ++c) beta[c] *= weight[c];
    if (order >= roulette_from_order_) {
      double survival = std::min(1.0, BounceEnergy(v, d, f, next, weight));
      if (!(rng.Uniform() < survival)) return;
      for (int c = 0; c < n; ++c) beta[c] /= survival;
    }
    v = next;
    ++order;
  }
}

}  // namespace aerial::reference
