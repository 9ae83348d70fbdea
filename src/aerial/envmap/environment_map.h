#pragma once
// Environment maps of the sky (`aerial envmap`): the radiance seen from one point in every
// direction, for image-based lighting in other renderers, computed per texel on the device
// (shaders/envmap/envmap.comp) with the lookups of aerial's sky and of `aerial probe`.
//
// Directions are in the scene frame of aerial/scene.h (x east, y north, z up; the point's local
// vertical is +z). Two layouts:
//  - lat-long (equirectangular), width = 2 height: texel (x, y) looks at zenith angle
//    180 (y + 0.5) / height degrees and compass azimuth 360 (x + 0.5) / width - 90 degrees, so the
//    top row is the zenith, the middle of the image the horizon, the centre column east (+x) and
//    the azimuth grows to the right (north at a quarter of the width, south at three quarters):
//    Blender's equirectangular convention for a Z-up world whose +x is east, which is OpenEXR's
//    lat-long envmap in the frame X = north, Y = up, Z = east (ImfEnvmap.h, up to its texel
//    centres at the poles and at both edges).
//  - cube: OpenEXR's cube envmap (six faces of side N stacked into N x 6N, ImfEnvmap.h's order
//    and orientation, texel directions from its Imf::CubeMap functions), in the same frame.
// The lower half is what aerial's sky shows there: the air in front of the bare planet, lit by the
// sun and the sky with the atmosphere's ground albedo.
#include <array>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "aerial/image.h"
#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/scene.h"

namespace aerial {

enum class EnvironmentLayout { kLatLong, kCube };

struct EnvironmentMapOptions {
  EnvironmentLayout layout = EnvironmentLayout::kLatLong;
  int size = 1024;          // lat-long: the height (the width is twice it); cube: a face's side
  double altitude_m = 0.0;  // above the planet's sphere
  Sun sun;
  bool sun_disc = false;    // the sun's disc in the map, or left to a separate light
};

struct EnvironmentMap {
  ImageRgbF image;  // linear radiance per texel, W/m^2/sr/nm, alpha 1
  // The sun's irradiance at the point on a surface facing it (W/m^2/nm, the tables' three
  // channels), through the air: what a separate sun light gives when the disc is left out.
  std::array<double, 3> sun_irradiance{};
};

// The image's width and height for the options.
std::array<int, 2> EnvironmentImageSize(const EnvironmentMapOptions& options);

// The world direction (unit, w 0) of each texel's centre into `out`, row-major, top row first:
// width x height texels, or face_size x 6 face_size.
void LatLongDirections(int width, int height, std::span<glm::vec4> out);
void CubeDirections(int face_size, std::span<glm::vec4> out);

// Throws Error naming --altitude-m for an altitude outside the atmosphere's [0, top - bottom].
EnvironmentMap RenderEnvironmentMap(const AtmosphereTables& tables, const EnvironmentMapOptions& options);

}  // namespace aerial
