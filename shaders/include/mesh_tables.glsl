// The tables that aerial's mesh passes (opaque_fragment.glsl, transparent.frag) read per pixel, at
// the bindings of the renderer's mesh layout (renderer.cpp, kMeshSlots), and the per-pixel
// aerial perspective read from them (kAerialPerPixel 1 or 2, frame.glsl): marched, its steps
// shadowed as the froxel volume's are (shadowed_march.glsl), or as two table reads.
#ifndef AERIAL_MESH_TABLES_GLSL
#define AERIAL_MESH_TABLES_GLSL
// The passes' variant for a sun high over every point that the marched per-pixel path reaches
// (aerial/render/sun_high_variant.h, Renderer::MeshPipelinesFor); the other modes march nothing.
// Included before anything else, so that transmittance.glsl takes it.
layout(constant_id = 4) const bool kSunHighEverywhere = false;
#define AERIAL_SUN_HIGH_EVERYWHERE kSunHighEverywhere
#include "aerial_perspective.glsl"
#ifndef AERIAL_SHADOW_BINDING
#define AERIAL_SHADOW_BINDING 8
#endif
#include "shadowed_march.glsl"
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 4) uniform sampler3D multiple_density_texture;
layout(set = 0, binding = 11) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 12) uniform sampler3D mie_texture;
layout(set = 0, binding = 13) uniform sampler3D multiple_texture;

// ray: the camera-relative unit view ray whose parameters r, mu, mu_s and nu are.
Inscatter GetMeshAerialPerspectivePerPixel(vec3 ray, float r, float mu, float mu_s, float nu, float distance) {
  if (kAerialPerPixel == AERIAL_MARCHED) {
    return GetShadowedSkyInscatterToPoint(transmittance_texture, multiple_density_texture, ray, r, mu, mu_s, nu,
                                          distance);
  }
  return GetAerialPerspectivePerPixel(transmittance_texture, multiple_density_texture, rayleigh_texture,
                                      mie_texture, multiple_texture, r, mu, mu_s, nu, distance);
}

#endif
