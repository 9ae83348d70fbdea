#version 450
#extension GL_GOOGLE_include_directive : require
// Sky-view correction pass, before the sky-view pass: the correction of the tables'
// inscatter (GetSkyInscatterCorrection, sky_lookup.glsl) at the lattice nodes of the sky-view
// table (sky_view.glsl), which sky_view.comp interpolates. It marches five suns along each ray
// (seven in daylight), which at every texel of the table would cost several times the lattice's
// 1,862 nodes at each rebuild; a frame under a moving sun rebuilds it every frame.
// The correction changes slowly over the table except across the horizon row, which no lattice
// cell spans. Since the correction also re-blends the multiple scattering in nu, it runs for a high
// sun too (the 3D tables need none: every node returns at once).
#include "blocks_not_inlined.glsl"
// The variant for a sun high over every lattice ray's marched suns (aerial/render/sun_high_variant.h,
// Renderer::RecordSkyViewCorrection), declared before the includes so that transmittance.glsl takes it.
layout(constant_id = 4) const bool kSunHighEverywhere = false;
#define AERIAL_SUN_HIGH_EVERYWHERE kSunHighEverywhere
#include "sky_lookup.glsl"
#include "sky_view.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4, rgba32f) writeonly uniform image2D rayleigh_correction;
layout(set = 0, binding = 5, rgba32f) writeonly uniform image2D mie_correction;
// The sky-view table's size, and the lattice rows [first, end) that this dispatch makes (the
// renderer makes the lattice in bands of rows: frame_cache_policy.h, SkyViewLatticeBandsToRemake).
layout(push_constant) uniform Size {
  ivec2 size;
  ivec2 rows;
} table;

void main() {
  ivec2 node = ivec2(gl_GlobalInvocationID.xy) + ivec2(0, table.rows.x);
  if (node.y >= table.rows.y || any(greaterThanEqual(node, GetSkyViewLatticeSize(table.size)))) return;
  SkyViewRay ray = GetSkyViewRay(GetSkyViewLatticeTexel(node, table.size), table.size);
  vec3 rayleigh, mie;
  GetSkyInscatterCorrection(transmittance_texture, rayleigh_texture, ray.r, ray.mu, ray.mu_s,
                            ray.nu, rayleigh, mie);
  imageStore(rayleigh_correction, node, vec4(rayleigh, 0.0));
  imageStore(mie_correction, node, vec4(mie, 0.0));
}
