#include "aerial/render/shadow_uniforms.h"

#include <glm/gtc/matrix_transform.hpp>

namespace aerial {

glm::dmat4 ClipFromRelative(const ShadowCascade& cascade, const glm::dvec3& camera_position) {
  return cascade.clip_from_world * glm::translate(glm::dmat4(1.0), camera_position);
}

ShadowUniforms MakeShadowUniforms(const ShadowCascades& cascades, const glm::dvec3& camera_position,
                                  const glm::dvec3& sun, bool enabled) {
  // Clip x, y in [-1, 1] -> tile u, v in [0, 1]; depth unchanged.
  glm::dmat4 tile_from_clip(1.0);
  tile_from_clip[0][0] = tile_from_clip[1][1] = 0.5;
  tile_from_clip[3] = glm::dvec4(0.5, 0.5, 0.0, 1.0);
  ShadowUniforms u{};
  for (int i = 0; i < kShadowCascades; ++i) {
    u.tile_from_relative[i] = ToColumnMajorFloats(tile_from_clip * ClipFromRelative(cascades[i], camera_position));
    u.texel_m[i] = float(cascades[i].texel_m);
  }
  u.sun_direction = {float(sun.x), float(sun.y), float(sun.z), 0.0f};
  u.cascades = {enabled ? kShadowCascades : 0, kShadowAtlasTilesPerRow, 0, 0};
  return u;
}

}  // namespace aerial
