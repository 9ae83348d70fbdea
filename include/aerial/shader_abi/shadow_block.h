#pragma once
// The std140 block of shaders/include/shadow.glsl (ShadowBlock): where each cascade of the sun's
// shadow map lies, as the frame's shaders look it up (render/shadow_uniforms.h fills it).
// tests/uniform_layout_test.cpp checks it member by member against the GLSL compiler's layout.
//
// All cascades share the light's axes, so a lookup projects a point once (three dot products
// with the axes) and each cascade only shifts and scales the result: far cheaper per fragment on
// a CPU rasterizer than a 4x4 matrix per cascade. Light coordinates here are relative to the
// camera (in meters along right, up and toward the sun), which keeps them small in float.
#include <array>

namespace aerial {

// The cascades of the sun's shadow map (render/shadow_cascades.h); shadow.glsl has the same.
inline constexpr int kShadowCascades = 4;

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
  // x: the largest distance of any caster from the planet's centre (m); yzw unused. A point
  // farther out with the sun above its horizon sees the sun past every caster.
  std::array<float, 4> casters;
};
static_assert(sizeof(ShadowUniforms) == (3 + 2 + 2 * kShadowCascades + 2) * 16);

}  // namespace aerial
