// The opaque fragment shaders' parts (opaque.frag, opaque_caching.frag): geometry seen through the
// air, L T + I_R P_R(nu) + I_M P_M(nu), with L the lit surface radiance from the vertices
// (opaque.vert), its sun part times the sun's visibility here, (I_R, I_M, T) from the froxel
// volume (per-pixel modes: from the tables) and nu from the fragment's own view ray. Geometry is
// drawn nearest first, so early depth tests skip this work for hidden fragments.
//
// The froxel volume is read per vertex and interpolated on triangles thin in depth
// (kFroxelsPerVertex, opaque.vert), per pixel at the fragment's screen position and distance on
// others, or after the pass, once per pixel in a full-screen pass. That pass
// (kAerialPerspectiveInFullScreenPass, aerial_composite.frag) is also where the per-pixel modes
// compute the segment by default: the fragment then writes its surface radiance and distance.
//
// The sun's visibility comes from one of three places:
//  - the shadow map (shadow.glsl), which is 1 everywhere with shadows off;
//  - the same, also written to a second color target (opaque_caching.frag): the screen's sun
//    visibility of the front-most surfaces once the pass ends;
//  - that target, read back at the fragment's pixel (kSunVisibilityFromCache): for a frame whose
//    camera, sun, shadow map and geometry are those of the frame that wrote it, so that each pixel
//    that survives the depth test reads what the lookup gave for that very surface
//    (Renderer::Record). On a CPU rasterizer the cascade choice, projection and filtered
//    comparison cost about a third of a still frame; one texel fetch replaces them.
#ifndef AERIAL_OPAQUE_FRAGMENT_GLSL
#define AERIAL_OPAQUE_FRAGMENT_GLSL
#include "mesh_tables.glsl"
#include "surface.glsl"
#include "ground_detail.glsl"
#define AERIAL_SHADOW_BINDING 8
#include "shadow.glsl"
layout(constant_id = 3) const int kSunVisibilityFromCache = 0;
layout(constant_id = 5) const bool kFroxelsPerVertex = false;
// Reads a benchmark leaves out to measure what each costs (aerial_bench_render): the froxel
// volume's (a constant segment instead), the sun visibility's (1 instead) and the whole shading
// (a constant radiance instead). 0 in every frame.
layout(constant_id = 6) const int kReadsLeftOut = 0;
const int kLeaveOutFroxelReads = 1, kLeaveOutSunVisibility = 2, kLeaveOutShading = 4;
layout(constant_id = 8) const bool kAerialPerspectiveInFullScreenPass = false;
layout(set = 0, binding = 5) uniform sampler3D rayleigh_froxels;
layout(set = 0, binding = 6) uniform sampler3D mie_froxels;
layout(set = 0, binding = 7) uniform sampler3D transmittance_froxels;
layout(set = 0, binding = 10) uniform sampler2D cached_sun_visibility;
layout(location = 0) in vec3 relative_position;
layout(location = 1) in vec3 sun_radiance;
layout(location = 2) in vec3 sky_radiance;
layout(location = 3) in vec3 surface_normal;
layout(location = 4) in vec3 vertex_rayleigh;
layout(location = 5) in vec3 vertex_mie;
layout(location = 6) in vec3 vertex_transmittance;
layout(location = 7) in vec3 shadow_coordinates[kShadowCascades];
layout(location = 11) flat in float ground_detail;

// The sun's visibility at the fragment (see above).
float GetFragmentSunVisibility() {
  if ((kReadsLeftOut & kLeaveOutSunVisibility) != 0) return 1.0;
  if (kSunVisibilityFromCache == 1) return texelFetch(cached_sun_visibility, ivec2(gl_FragCoord.xy), 0).r;
  return SunVisibilityFromCoordinates(relative_position, shadow_coordinates);
}

// The segment of air between the camera and the fragment (see above).
Inscatter GetFragmentSegment(vec3 ray, float r, float mu, float mu_s, float nu, float distance) {
  if (kAerialPerPixel != AERIAL_FROXELS) return GetMeshAerialPerspectivePerPixel(ray, r, mu, mu_s, nu, distance);
  if ((kReadsLeftOut & kLeaveOutFroxelReads) != 0) return Inscatter(vec3(1e-3), vec3(1e-4), vec3(0.9));
  if (kFroxelsPerVertex) return Inscatter(vertex_rayleigh, vertex_mie, vertex_transmittance);
  return GetAerialPerspective(rayleigh_froxels, mie_froxels, transmittance_froxels,
                              gl_FragCoord.xy / AERIAL_FRAME.viewport.xy, distance);
}

// The fragment's radiance at the camera, its surface's sun part times sun_visibility; with the
// aerial perspective applied in a full-screen pass, the surface's radiance and its distance.
vec4 GetFragmentRadiance(float sun_visibility) {
  if ((kReadsLeftOut & kLeaveOutShading) != 0) return vec4(0.05, 0.05, 0.05, 1.0);
  float distance = length(relative_position);
  vec3 ray = relative_position / distance;
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  float detail = GroundAlbedoDetailAt(relative_position, ground_detail);
  vec3 surface_radiance = ShadeLambertian(LambertianRadiance(detail * sun_radiance, detail * sky_radiance),
                                          normalize(surface_normal), sun_visibility);
  if (kAerialPerspectiveInFullScreenPass) return vec4(surface_radiance, distance);
  return vec4(ApplyAerialPerspective(surface_radiance, GetFragmentSegment(ray, r, mu, mu_s, nu, distance), nu), 1.0);
}

#endif
