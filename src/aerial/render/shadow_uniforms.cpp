#include "aerial/render/shadow_uniforms.h"

#include <glm/gtc/matrix_transform.hpp>

#include "aerial/scene/camera.h"

namespace aerial {

glm::dmat4 ClipFromRelative(const ShadowCascade& cascade, const glm::dvec3& camera_position) {
  return cascade.clip_from_world * glm::translate(glm::dmat4(1.0), camera_position);
}

ShadowUniforms MakeShadowUniforms(const ShadowCascades& cascades, const glm::dvec3& sun, const Camera& view,
                                  const CasterBounds& casters, bool enabled) {
  auto vec4 = [](const glm::dvec3& v) { return std::array<float, 4>{float(v.x), float(v.y), float(v.z), 0.0f}; };
  ShadowUniforms u{};
  u.toward_sun = vec4(sun);
  u.view_forward = vec4(Forward(view));
  for (int i = 0; i < kShadowCascades; ++i) {
    const ShadowCascade& c = cascades[i];
    const LightBasis b = MakeLightBasis(c.toward_sun);
    const glm::dvec3 camera(glm::dot(view.position, b.right), glm::dot(view.position, b.up),
                            glm::dot(view.position, b.toward_sun));
    u.cascade_right[i] = vec4(b.right);
    u.cascade_up[i] = vec4(b.up);
    u.cascade_toward_sun[i] = vec4(b.toward_sun);
    u.cascade_far_m[i] = float(c.far_m);
    u.cascade_origin[i] = {float(c.center_light.x - camera.x), float(c.center_light.y - camera.y), 0.0f,
                           float(c.depth_min_m - camera.z)};
    u.cascade_scale[i] = {float(0.5 / c.radius_m), float(1.0 / (c.depth_max_m - c.depth_min_m)), float(c.texel_m),
                          0.0f};
  }
  u.cascades = {enabled ? kShadowCascades : 0, 0, 0, 0};
  u.casters = {float(casters.top_radius_m), 0.0f, 0.0f, 0.0f};
  return u;
}

}  // namespace aerial
