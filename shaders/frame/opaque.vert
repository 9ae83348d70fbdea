#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque geometry: vertices are made camera-relative before projection (float precision), and
// lit here, per vertex (Gouraud): the Lambertian radiance from the sun and the sky (surface.glsl)
// varies slowly across a triangle of the terrain or a face of a landmark, and a CPU rasterizer
// then pays for the two table lookups once per vertex instead of once per fragment block of
// every triangle. The aerial perspective stays per fragment (opaque.frag).
#include "surface.glsl"
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler2D irradiance_texture;
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 albedo;
layout(location = 3) in float opacity;
layout(location = 0) out vec3 relative_position;
layout(location = 1) out vec3 surface_radiance;

void main() {
  relative_position = position - frame.camera_scene_position.xyz;
  surface_radiance = ShadeLambertian(transmittance_texture, irradiance_texture, relative_position,
                                     normal, albedo);
  gl_Position = frame.view_projection * vec4(relative_position, 1.0);
}
