#pragma once
// Radiance of scattering orders >= 1 along a view ray by path tracing (path_tracer.h). A path
// starts at an atmospheric scattering vertex on the first `length` meters of the view ray, drawn
// by DistanceSampler (stratified), with weight T(x, p) / pdf; its first direction is stratified.
// Only atmospheric in-scattering is counted: never the ground seen along the view ray.
#include "aerial/reference/medium.h"
#include "aerial/reference/monte_carlo_chunks.h"
#include "aerial/reference/vec3.h"
#include "aerial/reference/wavelength_groups.h"

namespace aerial::reference {

// World frame of a query: camera at (0, 0, r), view direction in the xz plane with zenith cosine
// mu, sun direction with zenith cosine mu_s and view . sun = nu (nu must be feasible, see
// ClampNu).
struct ViewFrame {
  Vec3 camera, view, sun;
};
ViewFrame MakeViewFrame(double r, double mu, double mu_s, double nu);

// The range of nu compatible with mu and mu_s is mu mu_s -+ sqrt((1 - mu^2)(1 - mu_s^2)).
double ClampNu(double mu, double mu_s, double nu);

// Orders first_order..max_order (lower orders are reported as zero), one estimate per group, from
// the same paths.
GroupOrderEstimates EstimateRadianceOrders(const WavelengthGroups& groups, double r, double mu, double mu_s,
                                           double nu, double length, int first_order, int max_order,
                                                   const MonteCarloOptions& options);
OrderEstimates EstimateRadianceOrders(const Medium& medium, double r, double mu, double mu_s,
                                      double nu, double length, int first_order, int max_order,
                                      const MonteCarloOptions& options);

}  // namespace aerial::reference
