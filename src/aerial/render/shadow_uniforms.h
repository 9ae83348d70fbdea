#pragma once
// The sun's shadow block (shader_abi/shadow_block.h) filled from the cascades (shadow_cascades.h)
// as the frame's shaders look them up from camera-relative positions. One per frame, since it
// follows the camera even while the shadow map is cached.
#include "aerial/render/frame_uniforms.h"
#include "aerial/render/shadow_cascades.h"
#include "aerial/shader_abi/shadow_block.h"

namespace aerial {

// The block for the cascades seen from the camera and the casters' top; with enabled = false,
// cascades.x = 0 (every visibility is 1).
ShadowUniforms MakeShadowUniforms(const ShadowCascades& cascades, const glm::dvec3& sun, const Camera& camera,
                                  const CasterBounds& casters, bool enabled);

// clip_from_world for camera-relative positions: the cascade's projection after the camera's
// translation, composed in double precision so that float keeps millimeters near the camera.
glm::dmat4 ClipFromRelative(const ShadowCascade& cascade, const glm::dvec3& camera_position);

}  // namespace aerial
