#include "aerial/render/shadow_uniforms.h"

#include <gtest/gtest.h>

#include "aerial/scene/camera.h"

namespace aerial {
namespace {

// The shader's lookup (shadow.glsl: light coordinates from the axes, then each cascade's shift and
// scale) lands where the depth pass's projection (clip_from_world) draws the same point: on the
// same texel of the tile within a thousandth of a texel, at the same depth.
TEST(ShadowUniforms, LookupMatchesTheDepthPassProjection) {
  CascadeFitInput in;
  in.camera.position = {2100.0, -3300.0, 140.0};
  in.camera.yaw_deg = 30.0;
  in.sun = DirectionFromZenithAzimuth(75.0, 290.0);
  in.casters = {glm::dvec3(0.0), 110e3};
  ShadowCascades cascades = FitShadowCascades(in);
  ShadowUniforms u = MakeShadowUniforms(cascades, in.sun, in.camera, in.casters, true);
  EXPECT_EQ(u.cascades[0], kShadowCascades);
  auto axis = [&](int a) { return glm::dvec3(u.light_axes[a][0], u.light_axes[a][1], u.light_axes[a][2]); };
  for (int i = 0; i < kShadowCascades; ++i) {
    const ShadowCascade& c = cascades[i];
    glm::dvec3 relative = Forward(in.camera) * (0.5 * (c.near_m + c.far_m)) + glm::dvec3(3.0, -7.0, 1.0);
    glm::dvec3 light(glm::dot(axis(0), relative), glm::dot(axis(1), relative), glm::dot(axis(2), relative));
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
    EXPECT_NEAR(glm::dot(glm::dvec3(u.view_forward[0], u.view_forward[1], u.view_forward[2]), relative),
                0.5 * (c.near_m + c.far_m), 8.0) << "the view depth that picks the cascade";
  }
  EXPECT_EQ(MakeShadowUniforms(cascades, in.sun, in.camera, in.casters, false).cascades[0], 0);
}

}  // namespace
}  // namespace aerial
