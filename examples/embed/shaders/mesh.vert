#version 450
#extension GL_GOOGLE_include_directive : require
// The engine's opaque meshes. Positions are made camera-relative before the projection (float
// keeps ~1 cm at 100 km that way), and the surface is lit per vertex by the sun and the sky
// through aerial's tables (surface.glsl), its sun and sky parts apart as a shadow would need; the
// sun's cosine is taken per fragment from the interpolated normal (ShadeLambertian).
#include "surface.glsl"
#include "bindings.glsl"
layout(location = 0) in vec3 position;  // world frame of aerial/scene.h, m
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 albedo;
layout(location = 0) out vec3 relative_position;
layout(location = 1) out vec3 sun_radiance;
layout(location = 2) out vec3 sky_radiance;
layout(location = 3) out vec3 surface_normal;

void main() {
  relative_position = position - AERIAL_FRAME.camera_scene_position.xyz;
  LambertianRadiance radiance =
      GetLambertianRadiance(transmittance_texture, irradiance_texture, relative_position, normal, albedo);
  sun_radiance = radiance.sun;
  sky_radiance = radiance.sky;
  surface_normal = normal;
  gl_Position = AERIAL_FRAME.view_projection * vec4(relative_position, 1.0);
}
