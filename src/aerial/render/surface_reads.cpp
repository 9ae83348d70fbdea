#include "aerial/render/surface_reads.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace aerial {

double SliceSpan(const FroxelGrid& grid, double edge_m, double distance_m) {
  const double d = std::max(distance_m, 0.0);
  return grid.depth * (grid.DepthCoordinate(d + edge_m) - grid.DepthCoordinate(d));
}

// The density profiles are 1 at the ground for Rayleigh and Mie (atmosphere.h); ozone's layer
// lies higher but is counted at its full density, which can only make the bound stricter.
AirScales MakeAirScales(const AtmosphereParameters& atmosphere) {
  AirScales air{.smallest_scale_height_m = std::numeric_limits<double>::infinity()};
  for (size_t c = 0; c < atmosphere.rayleigh_scattering.size(); ++c)
    air.ground_extinction_per_m =
        std::max(air.ground_extinction_per_m, atmosphere.rayleigh_scattering[c] + atmosphere.mie_extinction[c] +
                                                  atmosphere.absorption_extinction[c]);
  for (const DensityProfile* profile : {&atmosphere.rayleigh_density, &atmosphere.mie_density})
    for (const DensityProfileLayer& layer : profile->layers)
      if (layer.exp_term != 0.0 && layer.exp_scale_per_m != 0.0)
        air.smallest_scale_height_m = std::min(air.smallest_scale_height_m, 1.0 / std::abs(layer.exp_scale_per_m));
  return air;
}

bool ReadsFroxelsPerPixel(const FroxelGrid& grid, const AirScales& air, double edge_m, double rise_m,
                          double distance_m) {
  const bool thin_in_air = edge_m * air.ground_extinction_per_m <= kMaxEdgeOpticalThickness;
  const bool small_in_volume = SliceSpan(grid, edge_m, distance_m) <= kMaxSliceSpan &&
                               rise_m <= kMaxRiseOfScaleHeight * air.smallest_scale_height_m;
  return !thin_in_air && !small_in_volume;
}

double PerPixelReadsWithinM(const FroxelGrid& grid, const AirScales& air, double edge_m, double rise_m) {
  const bool thin_in_air = edge_m * air.ground_extinction_per_m <= kMaxEdgeOpticalThickness;
  if (thin_in_air) return 0.0;
  if (rise_m > kMaxRiseOfScaleHeight * air.smallest_scale_height_m) return std::numeric_limits<double>::infinity();
  // Bisection for where SliceSpan falls to kMaxSliceSpan, which it does: it shrinks as
  // 1 / sqrt(distance) far away.
  double near = 0.0, far = grid.far_m;
  if (SliceSpan(grid, edge_m, near) <= kMaxSliceSpan) return 0.0;
  while (SliceSpan(grid, edge_m, far) > kMaxSliceSpan) far *= 2.0;
  for (int i = 0; i < 64; ++i) {
    const double middle = 0.5 * (near + far);
    (SliceSpan(grid, edge_m, middle) <= kMaxSliceSpan ? far : near) = middle;
  }
  return far;
}

}  // namespace aerial
