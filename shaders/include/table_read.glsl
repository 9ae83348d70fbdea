// Reads of the precomputed tables (transmittance, sun band, irradiance, scattering): bilinear or
// trilinear between texel centres, clamped to the edge texels, as their samplers are made. Where
// the interpolation happens is the pipeline's TABLE_FILTERING, a specialization constant set from
// AERIAL_TABLE_FILTERING (src/aerial/vk/table_filtering.h):
//  - the sampler: one tap. Real GPUs interpolate with the weights quantized to
//    subTexelPrecisionBits (8 on NVIDIA, AMD and Intel: steps of 1/256 of a texel), lavapipe in
//    float, so the same tables could read differently on the two where neighbouring texels differ
//    a lot (the mu axis near the horizon, mu_s near the terminator);
//  - the shader, in float: 4 or 8 texel fetches, the same on every device;
//  - the shader with the weights rounded to 1/256: a hardware sampler emulated on lavapipe.
// A caller's shader that includes aerial's GLSL declares constant_id 16 with it: left unset, it
// reads through the sampler.
#ifndef AERIAL_TABLE_READ_GLSL
#define AERIAL_TABLE_READ_GLSL

const int TABLE_FILTERING_SAMPLER = 0;
const int TABLE_FILTERING_SHADER = 1;
const int TABLE_FILTERING_EMULATED_HARDWARE = 2;
layout(constant_id = 16) const int TABLE_FILTERING = TABLE_FILTERING_SAMPLER;

// The interpolation weights within a texel cell, rounded as a GPU's sampler rounds them when it
// is emulated.
vec3 GetTableFilterWeights(vec3 fraction) {
  if (TABLE_FILTERING == TABLE_FILTERING_EMULATED_HARDWARE) return round(fraction * 256.0) / 256.0;
  return fraction;
}

vec4 ReadTable(sampler2D table, vec2 uv) {
  if (TABLE_FILTERING == TABLE_FILTERING_SAMPLER) return textureLod(table, uv, 0.0);
  ivec2 size = textureSize(table, 0);
  vec2 x = uv * vec2(size) - 0.5;
  vec2 cell = floor(x);
  vec2 w = GetTableFilterWeights(vec3(x - cell, 0.0)).xy;
  ivec2 lo = clamp(ivec2(cell), ivec2(0), size - 1), hi = clamp(ivec2(cell) + 1, ivec2(0), size - 1);
  vec4 bottom = mix(texelFetch(table, lo, 0), texelFetch(table, ivec2(hi.x, lo.y), 0), w.x);
  vec4 top = mix(texelFetch(table, ivec2(lo.x, hi.y), 0), texelFetch(table, hi, 0), w.x);
  return mix(bottom, top, w.y);
}

vec4 ReadTable(sampler3D table, vec3 uvw) {
  if (TABLE_FILTERING == TABLE_FILTERING_SAMPLER) return textureLod(table, uvw, 0.0);
  ivec3 size = textureSize(table, 0);
  vec3 x = uvw * vec3(size) - 0.5;
  vec3 cell = floor(x);
  vec3 w = GetTableFilterWeights(x - cell);
  ivec3 lo = clamp(ivec3(cell), ivec3(0), size - 1), hi = clamp(ivec3(cell) + 1, ivec3(0), size - 1);
  vec4 near_bottom = mix(texelFetch(table, lo, 0), texelFetch(table, ivec3(hi.x, lo.y, lo.z), 0), w.x);
  vec4 near_top = mix(texelFetch(table, ivec3(lo.x, hi.y, lo.z), 0), texelFetch(table, ivec3(hi.xy, lo.z), 0), w.x);
  vec4 far_bottom = mix(texelFetch(table, ivec3(lo.xy, hi.z), 0), texelFetch(table, ivec3(hi.x, lo.y, hi.z), 0), w.x);
  vec4 far_top = mix(texelFetch(table, ivec3(lo.x, hi.yz), 0), texelFetch(table, hi, 0), w.x);
  return mix(mix(near_bottom, near_top, w.y), mix(far_bottom, far_top, w.y), w.z);
}

#endif
