#pragma once
// The built-in procedural terrain: a valley at the origin that opens north into a low corridor,
// walled and closed by ridged mountains 1-3 km high from ~5 km out to 85 km, fading to the bare
// planet sphere at kTerrainRadiusM so its edge leaves no cliff.
//
// Heights are measured along the local vertical (radially) above the planet sphere. (x, y) name
// the sea-level point below: the point of the sphere whose world-frame x and y they are (its z is
// sqrt(R^2 - x^2 - y^2) - R). Everything here is deterministic (noise.h).
#include <glm/glm.hpp>

#include "aerial/scene.h"

namespace aerial {

// The terrain covers horizontal distances up to this from the origin.
inline constexpr double kTerrainRadiusM = 100e3;

// Height in m above the sphere at the sea-level point (x, y); 0 at the origin.
double TerrainHeightM(double x_m, double y_m);

// An upper bound of TerrainHeightM: its highest peak is 3185 m (sampled every 50 m; terrain_test
// checks the bound), and every mesh of the terrain interpolates heights of the function.
inline constexpr double kTerrainMaxHeightM = 3300.0;
// A lower bound of TerrainHeightM: the valley's gentle hills dip about 2 m below the sphere.
inline constexpr double kTerrainMinHeightM = -10.0;

// The world point height_m above the sea-level point (x, y) on a sphere of radius R centered at
// (0, 0, -R): center + (R + height) * u, u the unit vector from the center through (x, y, .).
glm::dvec3 SurfacePoint(double x_m, double y_m, double height_m, double planet_radius_m);

// The inverse of SurfacePoint: the sea-level point on the radial line through the world point p
// (its x and y name it), and p's height above the terrain there.
glm::dvec3 SeaLevelPoint(const glm::dvec3& p, double planet_radius_m);
double HeightAboveTerrainM(const glm::dvec3& p, double planet_radius_m);

// A right-handed frame standing on the terrain at (x, y): origin on the surface, up radial (the
// local vertical, not the terrain normal), east and north horizontal there. Objects built in it
// stand upright even 100 km away, where the vertical tilts 0.9 degrees from +z.
struct GroundFrame {
  glm::dvec3 origin, east, north, up;
};
GroundFrame GroundFrameAt(double x_m, double y_m, double planet_radius_m);

// The terrain's surface point at the sea-level point (x, y): SurfacePoint at TerrainHeightM.
glm::dvec3 TerrainPoint(double x_m, double y_m, double planet_radius_m);

// A terrain vertex at surface point p whose normal is across_x x across_y: the differences of the
// surface points one grid step to either side in x and in y. Taking the normal over the grid's own
// spacing lets shading see the detail the geometry has (a smaller step would show sub-cell noise
// as shimmer). The albedo follows height and slope: grass, rock, snow.
Vertex TerrainVertex(const glm::dvec3& p, const glm::dvec3& across_x, const glm::dvec3& across_y,
                     double planet_radius_m);

// The terrain as its height function defines it at the sea-level point (x, y), in double
// precision, for checks of what the renderer draws: the surface point, the unit normal of the
// surface itself (its differences over kTerrainNormalStepM to either side in x and in y: the
// height function is smooth but at the ridges' crests, and its finest detail, the 560 m octave,
// makes the central difference's error ~(2 pi 0.5 / 560)^2 / 6 ~ 5e-6), and TerrainVertex's albedo.
struct TerrainSurface {
  glm::dvec3 point, normal, albedo;
};
inline constexpr double kTerrainNormalStepM = 0.5;
TerrainSurface TerrainSurfaceAt(double x_m, double y_m, double planet_radius_m);

// The terrain as one static opaque mesh named "terrain", centered on the scene origin: a polar
// grid whose rings are kTerrainMinStepM apart near the origin and then grow geometrically so
// that cells stay square (ring spacing = r * 2 pi / kTerrainSegments). 147K vertices and 294K
// triangles. The renderer draws the terrain with a level of detail that follows the camera
// (src/aerial/terrain/); this mesh is the fixed reference it is measured against
// (RenderOptions::terrain).
inline constexpr int kTerrainSegments = 360;
inline constexpr double kTerrainMinStepM = 4.0;
Mesh BuildTerrainMesh(double planet_radius_m);

}  // namespace aerial
