#pragma once
// The surface the scene itself has where a renderer drew opaque geometry, for checking that
// renderer's lighting against the CPU reference (validation/reference_sampling.h): the renderer's
// depth along the pixel's ray says where (geometry), the scene's description says what is there
// (point, normal, albedo), never the renderer's lighting.
//  - Meshes: the nearest hit of a CPU ray cast (scene/mesh_ray_cast.h), taken where it is at the
//    renderer's depth d within kMeshDepthTolerance d + 1 cm. Both draw the same float triangles;
//    the depth is interpolated in float (~1e-7 relative) and the ray rebuilt from the frame's float
//    matrices (~1e-6 rad), which moves the hit along a face seen at a grazing angle g by
//    ~1e-6 d / tan g: 1e-4 d allows g down to 0.6 degrees.
//  - The terrain: the renderer draws a level of detail whose triangles lie within a radial
//    distance eps of the height function's surface, eps K / d' <= error_px for the chunk's nearest
//    distance d' <= d and K its pixels per radian (lod_selection.h); eps is measured at
//    sample points, and the gap found between them reaches 1.25 times the bound (docs/design.md,
//    "Terrain"); skirts hang up to 0.1 m below that. So where the renderer's point at depth d lies
//    radially within 1.25 error_px d / K + 0.1 m of the surface, and the CPU finds no mesh in front
//    of it, it is terrain: the height function's surface point on its radial line is lit, with
//    that surface's normal and albedo (scene/terrain.h, TerrainSurfaceAt).
//  - Anything else (a mesh hit in front of the renderer's depth or beside it, a point off the
//    terrain): none, and the pixel is left out.
#include <glm/glm.hpp>
#include <optional>

#include "aerial/atmosphere.h"
#include "aerial/scene.h"

namespace aerial {

// A point of the scene's surface with what lights it: where, which way it faces, what it reflects.
struct SceneSurface {
  glm::dvec3 point{0.0};   // planet frame: the planet's centre at the origin
  glm::dvec3 normal{0.0};  // unit length
  Spectrum albedo{};       // Lambertian
};

inline constexpr double kMeshDepthTolerance = 1e-4;

// 1.25 error_px / K for a render height_px rows high (K as the renderer's terrain selection takes
// it, never fewer than 720 rows): the terrain's radial tolerance per meter of depth.
double TerrainTolerancePerM(const Camera& camera, int height_px, double terrain_error_px);

// The surface at depth_m along the unit ray (world frame) from scene.camera, its point in the
// planet frame (centre at the origin) for lighting.
std::optional<SceneSurface> SurfaceAtDepth(const Scene& scene, double planet_radius_m, const glm::dvec3& ray,
                                                double depth_m, double terrain_tolerance_per_m);

}  // namespace aerial
