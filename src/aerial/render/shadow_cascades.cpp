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

namespace {

// The bounding rectangle, in light coordinates across, of the slice [n, f] of view depth.
struct Rectangle {
  glm::dvec2 min, max;
  bool Holds(const Rectangle& r) const {
    return glm::all(glm::lessThanEqual(min, r.min)) && glm::all(glm::lessThanEqual(r.max, max));
  }
};
Rectangle SliceFootprint(const Camera& camera, double n, double f, double tan_x, double tan_y, const LightBasis& b) {
  Rectangle r{glm::dvec2(INFINITY), glm::dvec2(-INFINITY)};
  for (double depth : {n, f})
    for (double sx : {-1.0, 1.0})
      for (double sy : {-1.0, 1.0}) {
        glm::dvec3 p =
            camera.position + depth * (Forward(camera) + sx * tan_x * Right(camera) + sy * tan_y * Up(camera));
        glm::dvec2 light(glm::dot(p, b.right), glm::dot(p, b.up));
        r.min = glm::min(r.min, light);
        r.max = glm::max(r.max, light);
      }
  return r;
}

}  // namespace

namespace {

// The slice's bounding sphere's centre in light coordinates, and its footprint across.
struct SliceInLight {
  glm::dvec3 center;
  Rectangle footprint;
};
SliceInLight LocateSlice(const Camera& camera, double n, double f, double center_depth, double tan_x, double tan_y,
                         const LightBasis& b) {
  glm::dvec3 center = camera.position + Forward(camera) * center_depth;
  return {{glm::dot(center, b.right), glm::dot(center, b.up), glm::dot(center, b.toward_sun)},
          SliceFootprint(camera, n, f, tan_x, tan_y, b)};
}

double CastersTop(const CasterBounds& casters, const LightBasis& b) {
  return glm::dot(casters.center, b.toward_sun) + casters.radius_m;
}

}  // namespace

ShadowCascades FitShadowCascades(const CascadeFitInput& in, const HeldCascades& held,
                                 const std::array<bool, kShadowCascades>& keep_held_sun) {
  const LightBasis b = MakeLightBasis(in.sun);
  const double tan_y = std::tan(in.camera.vertical_fov_deg * std::numbers::pi / 360.0), tan_x = tan_y * in.aspect;
  const double casters_top = CastersTop(in.casters, b);
  ShadowCascades cascades;
  for (int i = 0; i < kShadowCascades; ++i) {
    const double near_m = ShadowSplitM(in.camera, i), far_m = ShadowSplitM(in.camera, i + 1);
    SliceSphere sphere = BoundSlice(near_m, far_m, tan_x, tan_y);
    const double slack_m = kShadowWindowSlack[i] * sphere.radius;
    if (const std::optional<ShadowCascade>& h = held[i];
        h && (h->toward_sun == b.toward_sun || keep_held_sun[i])) {
      // A held window is checked in the light's axes of the sun it was drawn for.
      const LightBasis held_basis = MakeLightBasis(h->toward_sun);
      const SliceInLight slice = LocateSlice(in.camera, near_m, far_m, sphere.center_depth, tan_x, tan_y, held_basis);
      if (h->slice_radius_m == sphere.radius && h->casters_top_m == CastersTop(in.casters, held_basis) &&
          h->near_m == near_m && h->far_m == far_m && Rectangle{h->casters_min, h->casters_max}.Holds(slice.footprint)) {
        glm::dvec3 offset = glm::abs(slice.center - h->center_light);
        double drift = std::max({offset.x, offset.y, offset.z}) / slack_m;
        if (drift <= 1.0) {
          cascades[i] = *h;
          cascades[i].drift = drift;
          continue;
        }
      }
    }
    const SliceInLight slice = LocateSlice(in.camera, near_m, far_m, sphere.center_depth, tan_x, tan_y, b);
    const glm::dvec3& light = slice.center;
    const Rectangle& footprint = slice.footprint;
    ShadowCascade& c = cascades[i];
    c.near_m = near_m;
    c.far_m = far_m;
    c.toward_sun = b.toward_sun;
    c.slice_radius_m = sphere.radius;
    c.casters_top_m = casters_top;
    // The window holds the sphere widened by the slack. The tile is widened by
    // kShadowMarginTexels on every side, and half a texel more for the snapping below, so that a
    // lookup anywhere in the slice stays inside the tile with its filter and offset.
    const double window_m = sphere.radius + slack_m;
    c.radius_m = window_m * in.tile_texels / (in.tile_texels - 2.0 * (kShadowMarginTexels + 0.5));
    c.texel_m = 2.0 * c.radius_m / in.tile_texels;
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
    // The casters' rectangle: the footprint widened by the slack, within the window's square.
    glm::dvec2 xy(c.center_light);
    c.casters_min = glm::max(footprint.min - slack_m, xy - c.radius_m);
    c.casters_max = glm::min(footprint.max + slack_m, xy + c.radius_m);
    c.planes = BoxPlanes(b, c.casters_min, c.casters_max, c.depth_min_m);
  }
  return cascades;
}

}  // namespace aerial
