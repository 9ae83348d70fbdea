#include "aerial/render/shadow_uniforms.h"

#include <gtest/gtest.h>

#include "aerial/scene/camera.h"

namespace aerial {
namespace {

// The shader's lookup (shadow.glsl: light coordinates from its cascade's axes, then the cascade's
// shift and scale) lands where the depth pass's projection (clip_from_world) draws the same point:
// on the same texel of the tile within a thousandth of a texel, at the same depth. The tiles here
// hold two suns, as under a moving sun (the first caught up, the others drawn for the sun before).
TEST(ShadowUniforms, LookupMatchesTheDepthPassProjection) {
  CascadeFitInput in;
  in.camera.position = {2100.0, -3300.0, 140.0};
  in.camera.yaw_deg = 30.0;
  in.sun = DirectionFromZenithAzimuth(75.0, 290.0);
  in.casters = {glm::dvec3(0.0), 110e3};
  HeldCascades before;
  for (int i = 0; i < kShadowCascades; ++i) before[i] = FitShadowCascades(in)[i];
  in.sun = DirectionFromZenithAzimuth(76.0, 291.0);
  ShadowCascades cascades = FitShadowCascades(in, before, {false, true, true, true});
  ASSERT_EQ(cascades[0].toward_sun, in.sun);
  ASSERT_NE(cascades[1].toward_sun, in.sun);
  ShadowUniforms u = MakeShadowUniforms(cascades, in.sun, in.camera, in.casters, true);
  EXPECT_EQ(u.cascades[0], kShadowCascades);
  auto vec3 = [](const std::array<float, 4>& v) { return glm::dvec3(v[0], v[1], v[2]); };
  EXPECT_NEAR(glm::distance(vec3(u.toward_sun), in.sun), 0.0, 1e-7);
  for (int i = 0; i < kShadowCascades; ++i) {
    const ShadowCascade& c = cascades[i];
    glm::dvec3 relative = Forward(in.camera) * (0.5 * (c.near_m + c.far_m)) + glm::dvec3(3.0, -7.0, 1.0);
    glm::dvec3 light(glm::dot(vec3(u.cascade_right[i]), relative), glm::dot(vec3(u.cascade_up[i]), relative),
                     glm::dot(vec3(u.cascade_toward_sun[i]), relative));
    const auto& o = u.cascade_origin[i];
    const auto& s = u.cascade_scale[i];
    glm::dvec2 uv = (glm::dvec2(light) - glm::dvec2(o[0], o[1])) * double(s[0]) + 0.5;
    double depth = (light.z - o[3]) * s[1];
    glm::dvec4 clip = c.clip_from_world * glm::dvec4(in.camera.position + relative, 1.0);
    double texel_uv = 1.0 / 1024.0;
    EXPECT_NEAR(uv.x, clip.x * 0.5 + 0.5, 1e-3 * texel_uv) << "cascade " << i;
    EXPECT_NEAR(uv.y, clip.y * 0.5 + 0.5, 1e-3 * texel_uv) << "cascade " << i;
    EXPECT_NEAR(depth, clip.z, 1e-6) << "cascade " << i;
    EXPECT_FLOAT_EQ(s[2], float(c.texel_m));
    EXPECT_FLOAT_EQ(u.cascade_far_m[i], float(c.far_m));
    EXPECT_NEAR(glm::dot(vec3(u.view_forward), relative), 0.5 * (c.near_m + c.far_m), 8.0)
        << "the view depth that picks the cascade";
  }
  EXPECT_EQ(MakeShadowUniforms(cascades, in.sun, in.camera, in.casters, false).cascades[0], 0);
}

}  // namespace
}  // namespace aerial
