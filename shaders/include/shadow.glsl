// The sun's visibility at a point, from the cascaded shadow map of the opaque scene
// (src/aerial/render/shadow_map.h, shadow_cascades.h): 1 where the sun's centre is seen, 0 where
// terrain or a mesh hides it, in between across a soft edge of about two texels.
//
// Usable from any stage: a fragment shader (surfaces) or a compute shader (the froxels' ray
// march). The including shader defines SHADOW_BINDING first: the ShadowBlock is bound there and
// the shadow map (a depth atlas sampled with comparison) at SHADOW_BINDING + 1, in set 0.
//   #define SHADOW_BINDING 10
//   #include "shadow.glsl"
//   float v = SunVisibility(relative_position, normal);  // on a surface
//   float a = SunVisibilityInAir(relative_position);     // a point in the air
// Positions are camera-relative world vectors, as everywhere in the frame's shaders (frame.glsl).
#ifndef AERIAL_SHADOW_GLSL
#define AERIAL_SHADOW_GLSL

#ifndef SHADOW_BINDING
#error "define SHADOW_BINDING (the ShadowBlock's binding; the shadow map takes the next) before shadow.glsl"
#endif

// 0: no shadows, every visibility is 1 and the shadow map is never read. A specialization
// constant (constant_id 1) so that raster pipelines without shadows compile the lookup out (a CPU
// rasterizer would run it under a uniform branch too); a pipeline that does not specialize it
// (compute) keeps 1 and reads ShadowBlock.cascades.x, which is 0 when shadows are off.
layout(constant_id = 1) const int kSunShadows = 1;

const int kShadowCascades = 4;

// Mirrored by aerial::ShadowUniforms (src/aerial/render/shadow_uniforms.h).
layout(std140, set = 0, binding = SHADOW_BINDING) uniform ShadowBlock {
  // Camera-relative world -> (u, v) in [0, 1] over the cascade's tile of the atlas, and the
  // light's depth in [0, 1], 1 toward the sun.
  mat4 tile_from_relative[kShadowCascades];
  vec4 texel_m;        // each cascade's texel, as a world length (m)
  vec4 sun_direction;  // xyz: unit vector toward the sun
  ivec4 cascades;      // x: cascades in use (0: shadows off); y: the atlas' tiles per row
} shadow;
layout(set = 0, binding = SHADOW_BINDING + 1) uniform sampler2DShadow shadow_map;

// PCF (Reeves et al. 1987) with the sampler's bilinear comparison (each tap compares the four
// nearest texels and blends the results bilinearly): four taps half a texel from the point, a
// 2x2-texel box over the bilinear comparison, which reaches 1.5 texels from the point in x and
// y and whose weights fall off smoothly (a tent of 3x3 texels), so edges move without popping.
const float kPcfReachTexels = 1.5;

// The bias, in texels of the cascade (t, the texel's world size). The depth map holds the
// nearest caster's depth at texel centres; a lit receiver plane tilted by theta from facing the
// sun (cos theta = n . sun) drifts in depth by r t tan(theta) across the filter's reach of r
// texels, so comparing the point itself would shadow the plane by itself ("acne"). Moving the
// point off the surface along its normal by k t (normal offset, Holbein 2011, "Normal offset
// shadows") raises it k t / cos(theta) above the plane along the sun's direction, which exceeds
// r t tan(theta) for every tilt as long as k >= r sin(theta): k = r = 1.5 texels covers all
// slopes. The same offset moves a shadow's start on the ground by at most k t (peter-panning):
// 1.5 texels, 16 cm in the first cascade. Points in the air (no normal) move k t toward the sun.
// The float depth's rounding (range 200 km at 2^-24 relative: 1.2 cm) stays far below k t.
const float kNormalOffsetTexels = 1.5;

// The first cascade whose tile holds the point with the filter's margin, or -1 beyond them all.
int SelectShadowCascade(vec3 relative_position) {
  for (int i = 0; i < shadow.cascades.x; ++i) {
    vec4 p = shadow.tile_from_relative[i] * vec4(relative_position, 1.0);
    float margin = (kPcfReachTexels + kNormalOffsetTexels + 1.0) * float(shadow.cascades.y) /
                   float(textureSize(shadow_map, 0).x);
    if (all(greaterThanEqual(p.xy, vec2(margin))) && all(lessThanEqual(p.xy, vec2(1.0 - margin))) &&
        p.z >= 0.0 && p.z <= 1.0)
      return i;
  }
  return -1;
}

// The filtered comparison of a point already biased, in cascade i.
float SampleShadowCascade(int i, vec3 biased_position) {
  vec3 p = (shadow.tile_from_relative[i] * vec4(biased_position, 1.0)).xyz;
  float tiles = float(shadow.cascades.y);
  vec2 atlas = (p.xy + vec2(i % shadow.cascades.y, i / shadow.cascades.y)) / tiles;
  vec2 half_texel = 0.5 / vec2(textureSize(shadow_map, 0));
  float lit = texture(shadow_map, vec3(atlas + vec2(-half_texel.x, -half_texel.y), p.z)) +
              texture(shadow_map, vec3(atlas + vec2(half_texel.x, -half_texel.y), p.z)) +
              texture(shadow_map, vec3(atlas + vec2(-half_texel.x, half_texel.y), p.z)) +
              texture(shadow_map, vec3(atlas + vec2(half_texel.x, half_texel.y), p.z));
  return 0.25 * lit;
}

// The sun's visibility in [0, 1] at a point in the air (the froxels' ray march): beyond the last
// cascade (100 km of view depth) or with shadows off, 1.
float SunVisibilityInAir(vec3 relative_position) {
  if (kSunShadows == 0) return 1.0;
  int i = SelectShadowCascade(relative_position);
  if (i < 0) return 1.0;
  return SampleShadowCascade(i, relative_position + shadow.sun_direction.xyz *
                                                      (kNormalOffsetTexels * shadow.texel_m[i]));
}

// The sun's visibility in [0, 1] at a point of a surface with the unit normal n (either side).
float SunVisibility(vec3 relative_position, vec3 normal) {
  if (kSunShadows == 0) return 1.0;
  int i = SelectShadowCascade(relative_position);
  if (i < 0) return 1.0;
  return SampleShadowCascade(i, relative_position + normal * (kNormalOffsetTexels * shadow.texel_m[i]));
}

#endif
