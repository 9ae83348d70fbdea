#include "aerial/render/shadow_cascades.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "aerial/scene/camera.h"

namespace aerial {
namespace {

// The smallest sphere around the slice [n, f] of view depth of a frustum whose sides have slopes
// tan_x and tan_y: on the axis at depth c, where the near and far corners are equally far,
// (f - c)^2 + f^2 k^2 = (c - n)^2 + n^2 k^2 with k^2 = tan_x^2 + tan_y^2, so
// c = (f + n) (1 + k^2) / 2; when that passes f, the far rectangle's own circle (c = f) holds all.
struct SliceSphere {
  double center_depth, radius;
};
SliceSphere BoundSlice(double n, double f, double tan_x, double tan_y) {
  double k2 = tan_x * tan_x + tan_y * tan_y;
  double c = std::min(f, 0.5 * (f + n) * (1.0 + k2));
  return {c, std::sqrt((f - c) * (f - c) + f * f * k2)};
}

// The plane dot(normal, p) + w >= 0 for dot(normal, p) >= offset.
glm::dvec4 HalfSpace(const glm::dvec3& normal, double offset) { return glm::dvec4(normal, -offset); }

std::array<glm::dvec4, 5> BoxPlanes(const LightBasis& b, glm::dvec2 lo, glm::dvec2 hi, double depth_min) {
  return {HalfSpace(b.right, lo.x), HalfSpace(-b.right, -hi.x), HalfSpace(b.up, lo.y),
          HalfSpace(-b.up, -hi.y), HalfSpace(b.toward_sun, depth_min)};
}

}  // namespace

LightBasis MakeLightBasis(const glm::dvec3& sun) {
  // Any axis not parallel to the sun gives a basis; +z unless the sun is near the zenith.
  glm::dvec3 helper = std::fabs(sun.z) < 0.99 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  glm::dvec3 right = glm::normalize(glm::cross(helper, sun));
  return {right, glm::cross(sun, right), sun};
}

double ShadowSplitM(const Camera& camera, int i) {
  if (i <= 0) return camera.near_m;
  return kFirstShadowSplitM * std::pow(kShadowFarM / kFirstShadowSplitM, double(i - 1) / (kShadowCascades - 1));
}

ShadowCascades FitShadowCascades(const CascadeFitInput& in) {
  const LightBasis b = MakeLightBasis(in.sun);
  const glm::dvec3 forward = Forward(in.camera);
  const double tan_y = std::tan(in.camera.vertical_fov_deg * std::numbers::pi / 360.0);
  const double casters_top = glm::dot(in.casters.center, b.toward_sun) + in.casters.radius_m;
  ShadowCascades cascades;
  for (int i = 0; i < kShadowCascades; ++i) {
    ShadowCascade& c = cascades[i];
    c.near_m = ShadowSplitM(in.camera, i);
    c.far_m = ShadowSplitM(in.camera, i + 1);
    SliceSphere sphere = BoundSlice(c.near_m, c.far_m, tan_y * in.aspect, tan_y);
    // The tile is widened by kShadowMarginTexels on every side, and half a texel more for the
    // snapping below, so that a lookup anywhere in the slice stays inside the tile with its filter
    // and offset.
    c.radius_m = sphere.radius * in.tile_texels / (in.tile_texels - 2.0 * (kShadowMarginTexels + 0.5));
    c.texel_m = 2.0 * c.radius_m / in.tile_texels;
    glm::dvec3 center = in.camera.position + forward * sphere.center_depth;
    glm::dvec3 light(glm::dot(center, b.right), glm::dot(center, b.up), glm::dot(center, b.toward_sun));
    c.center_light = glm::round(light / c.texel_m) * c.texel_m;
    c.depth_min_m = c.center_light.z - c.radius_m;
    c.depth_max_m = std::max(c.center_light.z + c.radius_m, casters_top);
    // Rows: x = (right . p - centre.x) / radius, y likewise, depth = (sun . p - min) / (max - min).
    double depth_range = c.depth_max_m - c.depth_min_m;
    glm::dmat4 m(0.0);
    for (int axis = 0; axis < 3; ++axis) {
      m[axis][0] = b.right[axis] / c.radius_m;
      m[axis][1] = b.up[axis] / c.radius_m;
      m[axis][2] = b.toward_sun[axis] / depth_range;
    }
    m[3] = glm::dvec4(-c.center_light.x / c.radius_m, -c.center_light.y / c.radius_m,
                      -c.depth_min_m / depth_range, 1.0);
    c.clip_from_world = m;
    glm::dvec2 xy(c.center_light);
    c.planes = BoxPlanes(b, xy - c.radius_m, xy + c.radius_m, c.depth_min_m);
  }
  return cascades;
}

std::array<glm::dvec4, 5> CascadesUnionPlanes(const ShadowCascades& cascades, const LightBasis& basis) {
  glm::dvec2 lo(INFINITY), hi(-INFINITY);
  double depth_min = INFINITY;
  for (const ShadowCascade& c : cascades) {
    lo = glm::min(lo, glm::dvec2(c.center_light) - c.radius_m);
    hi = glm::max(hi, glm::dvec2(c.center_light) + c.radius_m);
    depth_min = std::min(depth_min, c.depth_min_m);
  }
  return BoxPlanes(basis, lo, hi, depth_min);
}

}  // namespace aerial
