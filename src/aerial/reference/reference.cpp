#include "aerial/reference/reference.h"

#include <future>
#include <sstream>

#include "aerial/error.h"
#include "aerial/reference/geometry.h"
#include "aerial/reference/irradiance.h"
#include "aerial/reference/multiple_scattering.h"
#include "aerial/reference/optical_depth.h"
#include "aerial/reference/phase_functions.h"

namespace aerial::reference {
namespace {

constexpr const char* kWhere = "aerial::reference";
constexpr double kRadiusRounding = 1e-3;  // m: what rounding may add to a radius.
constexpr double kCosineRounding = 1e-12;

std::string Text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// Written as !(in range) so that NaN fails too.
double CheckCosine(const char* field, double v) {
  if (!(std::abs(v) <= 1.0 + kCosineRounding)) throw Error(field, Text(v), "[-1, 1]", kWhere);
  return ClampCosine(v);
}

void CheckOrders(int orders) {
  if (orders < 1) throw Error("orders", std::to_string(orders), ">= 1", kWhere);
}

void CheckOptions(const MonteCarloOptions& options) {
  if (options.paths_per_query < 1)
    throw Error("paths_per_query", std::to_string(options.paths_per_query), ">= 1", kWhere);
  if (options.threads < 0) throw Error("threads", std::to_string(options.threads), ">= 0 (0: all cores)", kWhere);
}

double CheckDistance(double d) {
  if (!(d >= 0.0)) throw Error("distance_m", Text(d), ">= 0 (or INFINITY)", kWhere);
  return d;
}

const AtmosphereParameters& CheckAtmosphere(const AtmosphereParameters& a) {
  if (!(a.bottom_radius_m > 0.0 && a.top_radius_m > a.bottom_radius_m))
    throw Error("top_radius_m", Text(a.top_radius_m), "> bottom_radius_m > 0", kWhere);
  if (!(a.sun_angular_radius_rad > 0.0 && a.sun_angular_radius_rad < 0.5))
    throw Error("sun_angular_radius_rad", Text(a.sun_angular_radius_rad), "(0, 0.5)", kWhere);
  if (!(std::abs(a.mie_phase_g) < 1.0)) throw Error("mie_phase_g", Text(a.mie_phase_g), "(-1, 1)", kWhere);
  return a;
}

}  // namespace

Reference::Reference(const AtmosphereParameters& atmosphere) : wavelengths_(CheckAtmosphere(atmosphere)) {}

double Reference::CheckRadius(double r) const {
  double bottom = medium().bottom_radius(), top = medium().top_radius();
  if (!(r >= bottom - kRadiusRounding && r <= top + kRadiusRounding)) {
    throw Error("r", Text(r), "[" + Text(bottom) + ", " + Text(top) + "] m (bottom to top radius)", kWhere);
  }
  return std::clamp(r, bottom, top);
}

double Reference::DistanceToBoundary(double r, double mu) const {
  r = CheckRadius(r);
  mu = CheckCosine("mu", mu);
  return RayIntersectsGround(r, mu) ? DistanceToInnerSphere(r, mu, medium().bottom_radius())
                                    : DistanceToOuterSphere(r, mu, medium().top_radius());
}

bool Reference::RayIntersectsGround(double r, double mu) const {
  return RayIntersectsInnerSphere(CheckRadius(r), CheckCosine("mu", mu), medium().bottom_radius());
}

Spectrum Reference::Transmittance(double r, double mu, double distance_m) const {
  double length = std::min(CheckDistance(distance_m), DistanceToBoundary(r, mu));
  return ComputeTransmittance(medium(), Accuracy::kReference, CheckRadius(r), CheckCosine("mu", mu), length);
}

Spectrum Reference::TransmittanceToBoundary(double r, double mu) const {
  return Transmittance(r, mu, INFINITY);
}

SingleScattering Reference::ComputeSingleScattering(double r, double mu, double mu_s, double nu,
                                                    double distance_m) const {
  double length = std::min(CheckDistance(distance_m), DistanceToBoundary(r, mu));
  r = CheckRadius(r);
  mu = CheckCosine("mu", mu);
  mu_s = CheckCosine("mu_s", mu_s);
  nu = ClampNu(mu, mu_s, CheckCosine("nu", nu));
  return reference::ComputeSingleScattering(medium(), r, mu, mu_s, nu, length);
}

Estimate Reference::ComputeRadiance(double r, double mu, double mu_s, double nu, int orders,
                                    double distance_m, const MonteCarloOptions& options) const {
  return RadianceOfGroups(std::span(this, 1), wavelengths_, r, mu, mu_s, nu, orders, distance_m, options).groups[0];
}

GroupEstimates Reference::RadianceOfGroups(std::span<const Reference> groups, const WavelengthGroups& wavelengths,
                                           double r, double mu, double mu_s, double nu, int orders,
                                           double distance_m, const MonteCarloOptions& options) const {
  CheckOrders(orders);
  CheckOptions(options);
  double length = std::min(CheckDistance(distance_m), DistanceToBoundary(r, mu));
  r = CheckRadius(r);
  mu = CheckCosine("mu", mu);
  mu_s = CheckCosine("mu_s", mu_s);
  nu = ClampNu(mu, mu_s, CheckCosine("nu", nu));
  GroupEstimates results{.groups = std::vector<Estimate>(groups.size())};
  // Single scattering is deterministic and runs on one thread: beside the Monte Carlo's threads,
  // so that it does not leave the others idle.
  std::future<std::vector<SingleScattering>> singles = std::async(std::launch::async, [&] {
    std::vector<SingleScattering> each;
    for (const Reference& group : groups) each.push_back(group.ComputeSingleScattering(r, mu, mu_s, nu, length));
    return each;
  });
  if (orders >= 2) {
    GroupOrderEstimates higher = EstimateRadianceOrders(wavelengths, r, mu, mu_s, nu, length, 2, orders, options);
    for (size_t g = 0; g < groups.size(); ++g) results.groups[g] = higher.groups[g].total;
    results.chunk_means = std::move(higher.chunk_totals);
  }
  double phase_r = RayleighPhase(nu), phase_m = MiePhase(nu);
  std::vector<SingleScattering> single_of = singles.get();
  for (size_t g = 0; g < groups.size(); ++g) {
    const SingleScattering& single = single_of[g];
    for (int c = 0; c < 3; ++c)
      results.groups[g].value[c] += single.rayleigh[c] * phase_r + single.mie[c] * phase_m;
  }
  return results;
}

Spectrum Reference::ComputeDirectIrradiance(double r, double mu_s) const {
  return reference::ComputeDirectIrradiance(medium(), Accuracy::kReference, CheckRadius(r),
                                            CheckCosine("mu_s", mu_s));
}

Estimate Reference::ComputeSkyIrradiance(double r, double mu_s, int orders,
                                         const MonteCarloOptions& options) const {
  return ComputeTiltedSkyIrradiance(r, mu_s, 1.0, mu_s, orders, options);
}

Estimate Reference::ComputeTiltedSkyIrradiance(double r, double mu_s, double mu_n, double nu_n, int orders,
                                               const MonteCarloOptions& options) const {
  return TiltedSkyIrradianceOfGroups(wavelengths_, r, mu_s, mu_n, nu_n, orders, options).groups[0];
}

GroupEstimates Reference::TiltedSkyIrradianceOfGroups(const WavelengthGroups& wavelengths, double r, double mu_s,
                                                      double mu_n, double nu_n, int orders,
                                                      const MonteCarloOptions& options) const {
  CheckOrders(orders);
  CheckOptions(options);
  r = CheckRadius(r);
  mu_s = CheckCosine("mu_s", mu_s);
  mu_n = CheckCosine("mu_n", mu_n);
  nu_n = ClampNu(mu_n, mu_s, CheckCosine("nu_n", nu_n));
  GroupOrderEstimates all = EstimateSkyIrradianceOrders(wavelengths, r, mu_s, mu_n, nu_n, orders, options);
  GroupEstimates results{.chunk_means = std::move(all.chunk_totals)};
  for (const OrderEstimates& group : all.groups) results.groups.push_back(group.total);
  return results;
}

double Reference::RayleighPhase(double nu) { return RayleighPhaseFunction(CheckCosine("nu", nu)); }

double Reference::MiePhase(double nu) const {
  return CornetteShanksPhaseFunction(medium().atmosphere().mie_phase_g, CheckCosine("nu", nu));
}

namespace {

std::vector<Reference> EachGroup(const std::vector<AtmosphereParameters>& groups) {
  std::vector<Reference> references;
  for (const AtmosphereParameters& group : groups) references.emplace_back(group);
  return references;
}

}  // namespace

ReferenceGroups::ReferenceGroups(const std::vector<AtmosphereParameters>& groups)
    : groups_(EachGroup(groups)), wavelengths_(groups) {}

GroupEstimates ReferenceGroups::ComputeRadiance(double r, double mu, double mu_s, double nu, int orders,
                                                double distance_m, const MonteCarloOptions& options) const {
  return groups_[0].RadianceOfGroups(groups_, wavelengths_, r, mu, mu_s, nu, orders, distance_m, options);
}

GroupEstimates ReferenceGroups::ComputeSkyIrradiance(double r, double mu_s, int orders,
                                                     const MonteCarloOptions& options) const {
  return ComputeTiltedSkyIrradiance(r, mu_s, 1.0, mu_s, orders, options);
}

GroupEstimates ReferenceGroups::ComputeTiltedSkyIrradiance(double r, double mu_s, double mu_n, double nu_n,
                                                           int orders, const MonteCarloOptions& options) const {
  return groups_[0].TiltedSkyIrradianceOfGroups(wavelengths_, r, mu_s, mu_n, nu_n, orders, options);
}

}  // namespace aerial::reference
