#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque geometry: the lit surface radiance (no aerial perspective yet) and its distance from the
// camera, for the composite pass.
#include "surface.glsl"
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler2D irradiance_texture;
layout(location = 0) in vec3 relative_position;
layout(location = 1) in vec3 surface_normal;
layout(location = 2) in vec3 surface_albedo;
layout(location = 0) out vec4 radiance_and_distance;

void main() {
  vec3 radiance = ShadeLambertian(transmittance_texture, irradiance_texture, relative_position,
                                  normalize(surface_normal), surface_albedo);
  radiance_and_distance = vec4(radiance, length(relative_position));
}
