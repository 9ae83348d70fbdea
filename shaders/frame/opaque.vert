#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque geometry: vertices are made camera-relative before projection (float precision), and
// lit here, per vertex (Gouraud): the Lambertian radiance from the sun and the sky (surface.glsl)
// varies slowly across a triangle of the terrain or a face of a landmark, and a CPU rasterizer
// then pays for the two table lookups once per vertex instead of once per fragment block of
// every triangle. The sun's part and the sky's part go out separately, because the sun's
// shadow (shadow.glsl) is sharp and is applied per fragment, from the shadow map coordinates
// computed here for every cascade and interpolated.
//
// On triangles thin in depth (kFroxelsPerVertex, chosen per draw by the renderer:
// src/aerial/render/surface_reads.h), the froxel volume is read here too and interpolated, as for
// transparent objects: O'Neil's split (GPU Gems 2, ch. 16), the scattering per vertex and the
// phase functions per pixel (opaque_fragment.glsl).
#include "aerial_perspective.glsl"
#define AERIAL_SHADOW_BINDING 8
#include "shadow.glsl"
layout(constant_id = 5) const bool kFroxelsPerVertex = false;
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
layout(location = 1) out vec3 sun_radiance;
layout(location = 2) out vec3 sky_radiance;
layout(location = 3) out vec3 surface_normal;
layout(location = 4) out vec3 vertex_rayleigh;
layout(location = 5) out vec3 vertex_mie;
layout(location = 6) out vec3 vertex_transmittance;
layout(location = 7) out vec3 shadow_coordinates[kShadowCascades];
// 1 where the draw is the ground's (its first instance is kGroundDetailInstance, the draw's own
// number as GPU-driven renderers pass it): ground_detail.glsl's albedo detail.
layout(location = 11) flat out float ground_detail;
const int kGroundDetailInstance = 1;

void main() {
  relative_position = position - AERIAL_FRAME.camera_scene_position.xyz;
  LambertianRadiance radiance =
      GetLambertianRadiance(transmittance_texture, irradiance_texture, relative_position, normal, albedo);
  sun_radiance = radiance.sun;
  sky_radiance = radiance.sky;
  surface_normal = normal;
  ground_detail = gl_InstanceIndex == kGroundDetailInstance ? 1.0 : 0.0;
  if (kSunShadows != 0) SurfaceShadowCoordinates(relative_position, normal, shadow_coordinates);
  gl_Position = AERIAL_FRAME.view_projection * vec4(relative_position, 1.0);
  Inscatter segment = Inscatter(vec3(0.0), vec3(0.0), vec3(1.0));
  if (kFroxelsPerVertex) {
    segment = GetAerialPerspectiveAtVertex(rayleigh_froxels, mie_froxels, transmittance_froxels, gl_Position,
                                           length(relative_position));
  }
  vertex_rayleigh = segment.rayleigh;
  vertex_mie = segment.mie;
  vertex_transmittance = segment.transmittance;
}
