// The opaque fragment shaders' parts (opaque.frag, opaque_caching.frag): geometry seen through the
// air, L T + I_R P_R(nu) + I_M P_M(nu), with L the lit surface radiance from the vertices
// (opaque.vert), its sun part times the sun's visibility here, (I_R, I_M, T) read from the froxel
// volume at the fragment's screen position and distance (per-pixel modes: from the tables) and nu
// from the fragment's own view ray. Geometry is drawn nearest first, so early depth tests skip
// this work for hidden fragments.
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
#define SHADOW_BINDING 8
#include "shadow.glsl"
layout(constant_id = 3) const int kSunVisibilityFromCache = 0;
layout(set = 0, binding = 5) uniform sampler3D rayleigh_froxels;
layout(set = 0, binding = 6) uniform sampler3D mie_froxels;
layout(set = 0, binding = 7) uniform sampler3D transmittance_froxels;
layout(set = 0, binding = 10) uniform sampler2D cached_sun_visibility;
layout(location = 0) in vec3 relative_position;
layout(location = 1) in vec3 sun_radiance;
layout(location = 2) in vec3 sky_radiance;
layout(location = 3) in vec3 surface_normal;

// The sun's visibility at the fragment (see above).
float GetFragmentSunVisibility() {
  if (kSunVisibilityFromCache == 1) return texelFetch(cached_sun_visibility, ivec2(gl_FragCoord.xy), 0).r;
  return SunVisibility(relative_position, normalize(surface_normal));
}

// The fragment's radiance at the camera, its surface's sun part times sun_visibility.
vec4 GetFragmentRadiance(float sun_visibility) {
  float distance = length(relative_position);
  vec3 ray = relative_position / distance;
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  Inscatter segment;
  if (kAerialPerPixel != AERIAL_FROXELS) {
    segment = GetMeshAerialPerspectivePerPixel(ray, r, mu, mu_s, nu, distance);
  } else {
    segment = GetAerialPerspective(rayleigh_froxels, mie_froxels, transmittance_froxels,
                                   gl_FragCoord.xy / frame.viewport.xy, distance);
  }
  vec3 surface_radiance =
      ShadeLambertian(LambertianRadiance(sun_radiance, sky_radiance), normalize(surface_normal), sun_visibility);
  return vec4(ApplyAerialPerspective(surface_radiance, segment, nu), 1.0);
}

#endif
