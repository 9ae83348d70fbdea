#include "aerial/render/shadow_uniforms.h"

#include <glm/gtc/matrix_transform.hpp>

#include "aerial/scene/camera.h"

namespace aerial {

glm::dmat4 ClipFromRelative(const ShadowCascade& cascade, const glm::dvec3& camera_position) {
  return cascade.clip_from_world * glm::translate(glm::dmat4(1.0), camera_position);
}

ShadowUniforms MakeShadowUniforms(const ShadowCascades& cascades, const glm::dvec3& sun, const Camera& view,
                                  const CasterBounds& casters, bool enabled) {
  const LightBasis b = MakeLightBasis(sun);
  const glm::dvec3& camera_position = view.position;
  const glm::dvec3 camera(glm::dot(camera_position, b.right), glm::dot(camera_position, b.up),
                          glm::dot(camera_position, b.toward_sun));
  ShadowUniforms u{};
  int axis = 0;
  for (const glm::dvec3& a : {b.right, b.up, b.toward_sun}) u.light_axes[axis++] = {float(a.x), float(a.y), float(a.z), 0.0f};
  glm::dvec3 forward = Forward(view);
  u.view_forward = {float(forward.x), float(forward.y), float(forward.z), 0.0f};
  for (int i = 0; i < kShadowCascades; ++i) {
    const ShadowCascade& c = cascades[i];
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
