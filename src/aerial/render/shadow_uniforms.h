#pragma once
// The std140 block of shaders/include/shadow.glsl (ShadowBlock): where each cascade of the sun's
// shadow map (shadow_cascades.h) lies, as the frame's shaders look it up from camera-relative
// positions. One per frame, since it follows the camera even while the shadow map is cached.
#include <array>

#include "aerial/render/frame_uniforms.h"
#include "aerial/render/shadow_cascades.h"

namespace aerial {

// The cascades' tiles in the shadow map's atlas: 2x2.
inline constexpr int kShadowAtlasTilesPerRow = 2;

struct alignas(16) ShadowUniforms {
  // Column-major; camera-relative world -> (u, v) over the cascade's tile in [0, 1], light depth.
  std::array<std::array<float, 16>, kShadowCascades> tile_from_relative;
  std::array<float, 4> texel_m;
  std::array<float, 4> sun_direction;
  std::array<int, 4> cascades;  // x: cascades in use (0: no shadows); y: tiles per atlas row
};
static_assert(sizeof(ShadowUniforms) == kShadowCascades * 64 + 3 * 16);
static_assert(kShadowCascades == 4, "shadow.glsl's kShadowCascades and texel_m (a vec4) assume 4");

// The block for the cascades seen from a camera at camera_position (scene frame); with
// enabled = false, cascades.x = 0 (every visibility is 1).
ShadowUniforms MakeShadowUniforms(const ShadowCascades& cascades, const glm::dvec3& camera_position,
                                  const glm::dvec3& sun, bool enabled);

// clip_from_world for camera-relative positions: the cascade's projection after the camera's
// translation, composed in double precision so that float keeps millimeters near the camera.
glm::dmat4 ClipFromRelative(const ShadowCascade& cascade, const glm::dvec3& camera_position);

}  // namespace aerial
