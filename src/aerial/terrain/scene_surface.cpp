#include "aerial/terrain/scene_surface.h"

#include <cmath>

#include "aerial/scene/mesh_ray_cast.h"
#include "aerial/scene/terrain.h"
#include "aerial/terrain/lod_selection.h"
#include "aerial/terrain/terrain_chunk.h"

namespace aerial {
namespace {

Spectrum ToSpectrum(const glm::dvec3& v) { return {v.r, v.g, v.b}; }

}  // namespace

double TerrainTolerancePerM(const Camera& camera, int height_px, double terrain_error_px) {
  // Only the pixels per radian are used: the aspect and the planet radius do not enter them.
  terrain::LodView view = terrain::MakeLodView(camera, 1.0, height_px, terrain_error_px, 0.0);
  return 1.25 * view.max_error_px / view.pixels_per_radian;
}

std::optional<SceneSurface> SurfaceAtDepth(const Scene& scene, double planet_radius_m, const glm::dvec3& ray,
                                                double depth_m, double terrain_tolerance_per_m) {
  const glm::dvec3 camera = scene.camera.position, planet_offset(0.0, 0.0, planet_radius_m);
  std::optional<MeshHit> hit = CastRay(scene.meshes, camera, ray);
  double mesh_tolerance = kMeshDepthTolerance * depth_m + 0.01;
  if (hit && std::fabs(hit->distance_m - depth_m) <= mesh_tolerance)
    return SceneSurface{.point = camera + hit->distance_m * ray + planet_offset,
                             .normal = hit->normal,
                             .albedo = ToSpectrum(hit->albedo)};
  if (!scene.terrain || (hit && hit->distance_m < depth_m)) return std::nullopt;
  glm::dvec3 point = camera + depth_m * ray;
  double terrain_tolerance = terrain_tolerance_per_m * depth_m + terrain::kSkirtMinimumM;
  if (std::fabs(HeightAboveTerrainM(point, planet_radius_m)) > terrain_tolerance) return std::nullopt;
  glm::dvec3 sea_level = SeaLevelPoint(point, planet_radius_m);
  TerrainSurface surface = TerrainSurfaceAt(sea_level.x, sea_level.y, planet_radius_m);
  return SceneSurface{.point = surface.point + planet_offset,
                           .normal = surface.normal,
                           .albedo = ToSpectrum(surface.albedo)};
}

}  // namespace aerial
