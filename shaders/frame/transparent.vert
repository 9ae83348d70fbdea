#version 450
#extension GL_GOOGLE_include_directive : require
// Transparent geometry, per VERTEX as engines do for particles and glass: the aerial perspective
// read from the froxel volume and the surface lit (Lambertian, two-sided: from whichever side
// faces the camera), both interpolated across the triangle, and the shadow map coordinates of
// every cascade. The phase functions and the sun's shadow (shadow.glsl, on the sun's part of the
// lighting) are still evaluated per pixel, in the fragment shader.
#include "aerial_perspective.glsl"
#include "surface.glsl"
#define AERIAL_SHADOW_BINDING 8
#include "shadow.glsl"
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler2D irradiance_texture;
layout(set = 0, binding = 5) uniform sampler3D rayleigh_froxels;
layout(set = 0, binding = 6) uniform sampler3D mie_froxels;
layout(set = 0, binding = 7) uniform sampler3D transmittance_froxels;
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 albedo;
layout(location = 3) in float opacity;
layout(location = 0) out vec3 relative_position;
layout(location = 1) out vec4 sun_radiance_opacity;
layout(location = 2) out vec3 vertex_rayleigh;
layout(location = 3) out vec3 vertex_mie;
layout(location = 4) out vec3 vertex_transmittance;
layout(location = 5) out vec3 sky_radiance;
layout(location = 6) out vec3 facing_normal;
layout(location = 7) out vec3 shadow_coordinates[kShadowCascades];

void main() {
  relative_position = position - AERIAL_FRAME.camera_scene_position.xyz;
  facing_normal = dot(normal, relative_position) > 0.0 ? -normal : normal;
  LambertianRadiance radiance =
      GetLambertianRadiance(transmittance_texture, irradiance_texture, relative_position, facing_normal, albedo);
  sun_radiance_opacity = vec4(radiance.sun, opacity);
  sky_radiance = radiance.sky;
  if (kSunShadows != 0) SurfaceShadowCoordinates(relative_position, facing_normal, shadow_coordinates);
  gl_Position = AERIAL_FRAME.view_projection * vec4(relative_position, 1.0);
  Inscatter inscatter = GetAerialPerspectiveAtVertex(rayleigh_froxels, mie_froxels, transmittance_froxels,
                                                     gl_Position, length(relative_position));
  vertex_rayleigh = inscatter.rayleigh;
  vertex_mie = inscatter.mie;
  vertex_transmittance = inscatter.transmittance;
}
