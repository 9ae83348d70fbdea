#pragma once
// The path tracer behind orders >= 2 (and the sky irradiance). A path is a chain of vertices,
// each an atmospheric scattering or a Lambertian ground reflection; each vertex raises the
// scattering order by one. At the k-th vertex, next-event estimation towards the sun adds the
// order-k contribution:
//  - atmosphere: beta * sum_species beta_s rho P(w_in . sun) * E_sun <V T>_disc;
//  - ground:     beta * albedo / pi * E_0 (direct irradiance, irradiance.h);
//  the disc's average <.>_disc estimated from one point of the disc where the sun is low
//  (solar_disc.h, SampleSunDiscTransmittance).
// Then the path continues, up to max_order vertices (kAllOrders: the whole series):
//  - direction: one sample from a mixture of the local phase lobes about w_in (Rayleigh exactly,
//    Cornette-Shanks through Henyey-Greenstein) or of the cosine lobe at the ground, and, with
//    probability 0.2 (if Mie's g > 0.3), of a Henyey-Greenstein lobe about the sun, which the
//    Mie forward peak of the next vertex's next-event estimate favours. Weight: f(w) / (mixture pdf of w).
//  - distance: if the ray hits the ground, the ground vertex is chosen with a probability that
//    balances the expected ground and atmosphere contributions; otherwise a scattering point on
//    the segment is drawn by DistanceSampler (forced scattering: paths never escape). The weight
//    is T / (probability x pdf).
//  - Russian roulette (Arvo & Kirk 1990) from vertex roulette_from_order on (monte_carlo.h): the path survives a
//    bounce with probability q = min(1, BounceEnergy), the fraction of energy the bounce carries
//    on, and its throughput is divided by q. Unbiased; it ends the series' paths where
//    their contribution fades. By default the orders the tables compute (up to 4) are never cut.
//    A path is stopped at kMaxPathVertices regardless: after 256 bounces, each survived with
//    q < 0.9 or so, the weight left is below 1e-11 of the path's start.
// This is an unbiased estimator of the recursion that Bruneton 2017 evaluates with tables
// (ComputeScatteringDensity, ComputeIndirectIrradiance, ComputeMultipleScattering), with the sun
// as a disc of irradiance E_sun.
#include <array>
#include <vector>

#include "aerial/reference/distance_sampler.h"
#include "aerial/reference/medium.h"
#include "aerial/reference/monte_carlo_chunks.h"
#include "aerial/reference/optical_depth.h"
#include "aerial/reference/vec3.h"
#include "aerial/reference/wavelength_groups.h"

namespace aerial::reference {

struct PathVertex {
  Vec3 p;       // world position (planet centre at the origin).
  Vec3 w_in;    // direction of travel of the path into the vertex (from the camera side).
  bool ground;  // Lambertian ground reflection, else atmospheric scattering.
};

inline constexpr int kMaxPathVertices = 256;

// Not thread-safe (scratch storage): one per thread.
class PathTracer {
 public:
  // Contributions of orders below first_order are not computed (their next-event estimates are
  // skipped), orders above max_order not traced. Paths are sampled from groups.sampling() and
  // weighted at every channel of `groups` (wavelength_groups.h).
  PathTracer(const WavelengthGroups& groups, Vec3 sun, int first_order, int max_order, int roulette_from_order);

  // Continues a path whose order-th vertex is v, reached with throughput beta, adding each order's
  // contribution to sums[min(order, sums.size() - 1)] (monte_carlo.h, kReportedOrders). first_u, if given, is the (stratified) 2D sample of the first
  // direction.
  void Continue(PathVertex v, Channels beta, int order, Rng& rng,
                const std::array<double, 2>* first_u, std::vector<Channels>& sums);

  // Samples the next vertex along the ray from p in direction w; *weight gets T / probability.
  // Returns false for an empty segment, but for a ray from the ground into it, which meets it at p.
  bool SampleSegment(Vec3 p, Vec3 w, double u_choice, double u_distance, PathVertex* next,
                     Channels* weight);

  // Sample a direction w from the mixture of the local lobe (the phase functions about v.w_in, or
  // the cosine about `normal`) and the sun lobe, and return f(w) / pdf(w), with f the
  // phase-weighted scattering coefficient sum_species beta_s rho P(w_in . w) (atmosphere) or
  // cos / pi (surface, the same at every wavelength; the albedo is the caller's).
  Channels SampleAtmosphereDirection(const PathVertex& v, const Densities& d, double u_lobe,
                                     std::array<double, 2> u, Vec3* w) const;
  double SampleSurfaceDirection(Vec3 normal, double u_lobe, std::array<double, 2> u, Vec3* w) const;

 private:
  // The bounce from v to next as a dimensionless fraction of energy, the largest over channels:
  // the weights f (per meter at an atmospheric vertex) and T / p (meters towards an atmospheric
  // vertex) are made unitless by the extinction coefficients at both ends, which gives about the
  // single-scattering albedo times the chance of scattering before leaving the atmosphere (the
  // ground's albedo times the transmittance to it, for a ground vertex).
  double BounceEnergy(const PathVertex& v, const Densities& d, const Channels& f, const PathVertex& next,
                      const Channels& weight) const;
  Channels AtmosphereNextEvent(const PathVertex& v, const Densities& d, Rng& rng) const;
  Channels GroundNextEvent(const PathVertex& v, Rng& rng) const;

  const WavelengthGroups& groups_;
  const Medium& medium_;  // groups_.sampling()
  Vec3 sun_;
  int first_order_, max_order_, roulette_from_order_;
  double sun_lobe_;  // mixture probability of the sun lobe.
  RayColumns columns_;
  DistanceSampler distances_;
};

}  // namespace aerial::reference
