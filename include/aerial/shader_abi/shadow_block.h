#pragma once
// The std140 block of shaders/include/shadow.glsl (ShadowBlock): where each cascade of the sun's
// shadow map lies, as the frame's shaders look it up (render/shadow_uniforms.h fills it).
// tests/uniform_layout_test.cpp checks it member by member against the GLSL compiler's layout.
//
// Each cascade has the light's axes of the sun it was drawn for: under a moving sun the tiles are
// redrawn one a frame (render/frame_cache_policy.h), so for a few frames they may hold different
// suns. A lookup picks its cascade's axes by selects of uniform values, then projects the point
// with three dot products and shifts and scales the result: far cheaper per fragment on a CPU
// rasterizer than a 4x4 matrix per cascade. Light coordinates here are relative to the camera (in
// meters along right, up and toward the sun), which keeps them small in float.
#include <array>

namespace aerial {

// The cascades of the sun's shadow map (render/shadow_cascades.h); shadow.glsl has the same.
inline constexpr int kShadowCascades = 4;

// The cascades' tiles in the shadow map's atlas: 2x2 (shadow.glsl has the same constant).
inline constexpr int kShadowAtlasTilesPerRow = 2;
static_assert(kShadowAtlasTilesPerRow * kShadowAtlasTilesPerRow >= kShadowCascades);

struct alignas(16) ShadowUniforms {
  std::array<float, 4> toward_sun;    // xyz: the sun's direction now
  std::array<float, 4> view_forward;  // xyz: the camera's forward axis
  // Per cascade: the light's axes of the sun its tile was drawn for (xyz; w unused).
  std::array<std::array<float, 4>, kShadowCascades> cascade_right;
  std::array<std::array<float, 4>, kShadowCascades> cascade_up;
  std::array<std::array<float, 4>, kShadowCascades> cascade_toward_sun;
  std::array<float, 4> cascade_far_m;  // each cascade's last view depth
  // Per cascade: its tile's centre in camera-relative light coordinates (x, y) and the light
  // coordinate of depth 0 (w); z unused.
  std::array<std::array<float, 4>, kShadowCascades> cascade_origin;
  // Per cascade: x tile units per meter across (1 / (2 radius)), y depth per meter (1 / range),
  // z the texel's world size (m); w unused.
  std::array<std::array<float, 4>, kShadowCascades> cascade_scale;
  std::array<int, 4> cascades;  // x: cascades in use (0: no shadows)
  // x: the largest distance of any caster from the planet's centre (m); yzw unused. A point
  // farther out with the sun above its horizon sees the sun past every caster.
  std::array<float, 4> casters;
};
static_assert(sizeof(ShadowUniforms) == (2 + 5 * kShadowCascades + 3) * 16);

}  // namespace aerial
