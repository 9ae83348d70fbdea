#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque geometry: vertices are made camera-relative before projection (float precision), and
// lit here, per vertex (Gouraud): the Lambertian radiance from the sun and the sky (surface.glsl)
// varies slowly across a triangle of the terrain or a face of a landmark, and a CPU rasterizer
// then pays for the two table lookups once per vertex instead of once per fragment block of
// every triangle. The sun's part and the sky's part go out separately, because the sun's
// shadow (shadow.glsl) is sharp and is applied per fragment; so is the aerial perspective
// (opaque.frag).
#include "surface.glsl"
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler2D irradiance_texture;
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 albedo;
layout(location = 3) in float opacity;
layout(location = 0) out vec3 relative_position;
layout(location = 1) out vec3 sun_radiance;
layout(location = 2) out vec3 sky_radiance;
layout(location = 3) out vec3 surface_normal;

void main() {
  relative_position = position - frame.camera_scene_position.xyz;
  LambertianRadiance radiance =
      GetLambertianRadiance(transmittance_texture, irradiance_texture, relative_position, normal, albedo);
  sun_radiance = radiance.sun;
  sky_radiance = radiance.sky;
  surface_normal = normal;
  gl_Position = frame.view_projection * vec4(relative_position, 1.0);
}
