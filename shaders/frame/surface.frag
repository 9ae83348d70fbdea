#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque geometry's lit surface radiance (opaque.vert, shadowed as in opaque.frag) without aerial
// perspective, and its distance from the camera: what Renderer::ReadSurface draws on request, for
// checks against a reference that applies its own aerial perspective. Frames use opaque.frag.
#include "surface.glsl"
#include "ground_detail.glsl"
#define AERIAL_SHADOW_BINDING 8
#include "shadow.glsl"
// 1: the sun's part included (times its visibility); 0: the sky's part alone (SurfaceLight).
layout(constant_id = 2) const int kSunPart = 1;
layout(location = 0) in vec3 relative_position;
layout(location = 1) in vec3 sun_radiance;
layout(location = 2) in vec3 sky_radiance;
layout(location = 3) in vec3 surface_normal;
layout(location = 7) in vec3 shadow_coordinates[kShadowCascades];
layout(location = 11) flat in float ground_detail;
layout(location = 0) out vec4 radiance_and_distance;

void main() {
  vec3 normal = normalize(surface_normal);
  float visibility = kSunPart == 0 ? 0.0 : SunVisibilityFromCoordinates(relative_position, shadow_coordinates);
  float detail = GroundAlbedoDetailAt(relative_position, ground_detail);
  radiance_and_distance = vec4(
      ShadeLambertian(LambertianRadiance(detail * sun_radiance, detail * sky_radiance), normal, visibility),
      length(relative_position));
}
