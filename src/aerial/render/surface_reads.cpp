#include "aerial/render/surface_reads.h"

#include <algorithm>

namespace aerial {

double SliceSpan(const FroxelGrid& grid, double edge_m, double distance_m) {
  const double d = std::max(distance_m, 0.0);
  return grid.depth * (grid.DepthCoordinate(d + edge_m) - grid.DepthCoordinate(d));
}

// The density profiles are 1 at the ground for Rayleigh and Mie (atmosphere.h); ozone's layer
// lies higher but is counted at its full density, which can only make the bound stricter.
double GroundExtinctionPerM(const AtmosphereParameters& atmosphere) {
  double most = 0.0;
  for (size_t c = 0; c < atmosphere.rayleigh_scattering.size(); ++c)
    most = std::max(most, atmosphere.rayleigh_scattering[c] + atmosphere.mie_extinction[c] +
                              atmosphere.absorption_extinction[c]);
  return most;
}

bool ReadsFroxelsPerPixel(const FroxelGrid& grid, double ground_extinction_per_m, double edge_m,
                          double distance_m) {
  const bool thin_in_air = edge_m * ground_extinction_per_m <= kMaxEdgeOpticalThickness;
  return !thin_in_air && SliceSpan(grid, edge_m, distance_m) > kMaxSliceSpan;
}

}  // namespace aerial
