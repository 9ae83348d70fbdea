#pragma once
// The built-in procedural terrain: a valley at the origin that opens north into a low corridor,
// walled and closed by ridged mountains 1-3 km high from ~5 km out to 85 km, fading to the bare
// planet sphere at kTerrainRadiusM so its edge leaves no cliff.
//
// Heights are measured along the local vertical (radially) above the planet sphere. (x, y) name
// the sea-level point below: the point of the sphere whose world-frame x and y they are (its z is
// sqrt(R^2 - x^2 - y^2) - R). Everything here is deterministic (noise.h).
#include <glm/glm.hpp>

#include "aerial/scene/scene.h"

namespace aerial {

// The terrain covers horizontal distances up to this from the origin.
inline constexpr double kTerrainRadiusM = 100e3;

// Height in m above the sphere at the sea-level point (x, y); 0 at the origin.
double TerrainHeightM(double x_m, double y_m);

// The world point height_m above the sea-level point (x, y) on a sphere of radius R centered at
// (0, 0, -R): center + (R + height) * u, u the unit vector from the center through (x, y, .).
glm::dvec3 SurfacePoint(double x_m, double y_m, double height_m, double planet_radius_m);

// A right-handed frame standing on the terrain at (x, y): origin on the surface, up radial (the
// local vertical, not the terrain normal), east and north horizontal there. Objects built in it
// stand upright even 100 km away, where the vertical tilts 0.9 degrees from +z.
struct GroundFrame {
  glm::dvec3 origin, east, north, up;
};
GroundFrame GroundFrameAt(double x_m, double y_m, double planet_radius_m);

// The terrain as one opaque mesh named "terrain": a polar grid around the origin whose rings are
// kTerrainMinStepM apart near the camera and then grow geometrically so that cells stay square
// (ring spacing = r * 2 pi / kTerrainSegments), keeping triangles at a similar angular size from
// the origin at every distance.
inline constexpr int kTerrainSegments = 360;
inline constexpr double kTerrainMinStepM = 4.0;
Mesh BuildTerrainMesh(double planet_radius_m);

}  // namespace aerial
