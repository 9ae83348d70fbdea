#include "aerial/export/ground.h"

#include "aerial/scene/terrain.h"

namespace aerial {

bool Ground::Below(const glm::dvec3& point) const {
  const double altitude = glm::length(point - glm::dvec3(0.0, 0.0, -planet_radius_m_)) - planet_radius_m_;
  if (!terrain_) return altitude < 0.0;
  // No terrain reaches kTerrainMaxHeightM: above it, the noise of TerrainHeightM need not be
  // evaluated (most of a volume is air far above the ground).
  if (altitude >= kTerrainMaxHeightM) return false;
  return HeightAboveTerrainM(point, planet_radius_m_) < 0.0;
}

}  // namespace aerial
