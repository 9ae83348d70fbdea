#pragma once
// The std140 block of shaders/include/shadow.glsl (ShadowBlock): where each cascade of the sun's
// shadow map (shadow_cascades.h) lies, as the frame's shaders look it up from camera-relative
// positions. One per frame, since it follows the camera even while the shadow map is cached.
//
// All cascades share the light's axes, so a lookup projects a point once (three dot products
// with the axes) and each cascade only shifts and scales the result: far cheaper per fragment on
// a CPU rasterizer than a 4x4 matrix per cascade. Light coordinates here are relative to the
// camera (in meters along right, up and toward the sun), which keeps them small in float.
#include <array>

#include "aerial/render/frame_uniforms.h"
#include "aerial/render/shadow_cascades.h"

namespace aerial {

// The cascades' tiles in the shadow map's atlas: 2x2 (shadow.glsl has the same constant).
inline constexpr int kShadowAtlasTilesPerRow = 2;
static_assert(kShadowAtlasTilesPerRow * kShadowAtlasTilesPerRow >= kShadowCascades);

struct alignas(16) ShadowUniforms {
  std::array<std::array<float, 4>, 3> light_axes;  // right, up, toward the sun (xyz)
  std::array<float, 4> view_forward;               // the camera's forward axis (xyz)
  std::array<float, 4> cascade_far_m;              // each cascade's last view depth
  // Per cascade: its tile's centre in camera-relative light coordinates (x, y) and the light
  // coordinate of depth 0 (w); z unused.
  std::array<std::array<float, 4>, kShadowCascades> cascade_origin;
  // Per cascade: x tile units per meter across (1 / (2 radius)), y depth per meter (1 / range),
  // z the texel's world size (m); w unused.
  std::array<std::array<float, 4>, kShadowCascades> cascade_scale;
  std::array<int, 4> cascades;  // x: cascades in use (0: no shadows)
};
static_assert(sizeof(ShadowUniforms) == (3 + 2 + 2 * kShadowCascades + 1) * 16);

// The block for the cascades seen from the camera; with enabled = false, cascades.x = 0 (every
// visibility is 1).
ShadowUniforms MakeShadowUniforms(const ShadowCascades& cascades, const glm::dvec3& sun, const Camera& camera,
                                  bool enabled);

// clip_from_world for camera-relative positions: the cascade's projection after the camera's
// translation, composed in double precision so that float keeps millimeters near the camera.
glm::dmat4 ClipFromRelative(const ShadowCascade& cascade, const glm::dvec3& camera_position);

}  // namespace aerial
