// The sun's visibility at a point, from the cascaded shadow map of the opaque scene
// (src/aerial/render/shadow_map.h, shadow_cascades.h): 1 where the sun's centre is seen, 0 where
// terrain or a mesh hides it, in between across a soft edge about one texel wide.
//
// Usable from any stage: a fragment shader (surfaces) or a compute shader (the froxels' ray
// march). The including shader defines AERIAL_SHADOW_BINDING first: the ShadowBlock is bound there and
// the shadow map (a depth atlas sampled with comparison) at AERIAL_SHADOW_BINDING + 1, in set 0.
//   #define AERIAL_SHADOW_BINDING 8
//   #include "shadow.glsl"
//   float v = SunVisibility(relative_position, normal);  // on a surface
//   ShadowRay r = MakeShadowRay(ray, camera_planet_position);  // points in the air along a ray
//   float a = SunVisibilityOnRay(r, t);
// Positions are camera-relative world vectors, as everywhere in the frame's shaders (frame.glsl).
#ifndef AERIAL_SHADOW_GLSL
#define AERIAL_SHADOW_GLSL
#extension GL_EXT_control_flow_attributes : require

#ifndef AERIAL_SHADOW_BINDING
#error "define AERIAL_SHADOW_BINDING (the ShadowBlock's binding; the shadow map takes the next) before shadow.glsl"
#endif

// 0: no shadows, every visibility is 1 and the shadow map is never read. A specialization
// constant (constant_id 1) so that raster pipelines without shadows compile the lookup out (a CPU
// rasterizer would run it under a uniform branch too); a pipeline that does not specialize it
// (compute) keeps 1 and reads ShadowBlock.cascades.x, which is 0 when shadows are off.
layout(constant_id = 1) const int kSunShadows = 1;

const int kShadowCascades = 4;
const int kShadowAtlasTilesPerRow = 2;  // the cascades' tiles in the atlas: 2x2

// Mirrored by aerial::ShadowUniforms (aerial/shader_abi/shadow_block.h). Light coordinates
// are relative to the camera, in meters along the light's axes.
layout(std140, set = 0, binding = AERIAL_SHADOW_BINDING) uniform ShadowBlock {
  vec4 toward_sun;                         // xyz: the sun's direction now
  vec4 view_forward;                       // xyz: the camera's forward axis
  // Per cascade, the light's axes of the sun its tile was drawn for: under a moving sun the tiles
  // catch up one a frame (src/aerial/render/frame_cache_policy.h).
  vec4 cascade_right[kShadowCascades];
  vec4 cascade_up[kShadowCascades];
  vec4 cascade_toward_sun[kShadowCascades];
  vec4 cascade_far_m;                      // each cascade's last view depth (m)
  vec4 cascade_origin[kShadowCascades];    // xy: the tile's centre; w: the light coordinate of depth 0
  vec4 cascade_scale[kShadowCascades];     // x: tile units per m; y: depth per m; z: texel (m)
  ivec4 cascades;  // x: cascades in use (0: shadows off)
  vec4 casters;    // x: the largest distance of any caster from the planet's centre (m)
} shadow;
layout(set = 0, binding = AERIAL_SHADOW_BINDING + 1) uniform sampler2DShadow shadow_map;

// PCF (Reeves et al. 1987) in its cheapest form: one lookup through the sampler's bilinear
// comparison, which compares the point's depth with the four nearest texels and blends the four
// results bilinearly (a 2x2-texel tent), so a shadow's edge is smooth across one texel and moves
// without popping. Four such taps half a texel apart (a 3x3-texel tent) looked softer but made
// the lookup cost 1.3 times as much on lavapipe (docs/design.md, "Shadows"). The four texels lie within
// one texel of the point along each axis: the filter's reach r = 1.

// The bias, in texels of the cascade (t, the texel's world size). The depth map holds the
// nearest caster's depth at texel centres; a lit receiver plane tilted by theta from facing the
// sun (cos theta = n . sun) drifts in depth by up to sqrt(2) r t tan(theta) across the filter's
// reach of r texels along each axis, so comparing the point itself would shadow the plane by
// itself ("acne"). Moving the point off the surface along its normal by k t (normal offset,
// Holbein 2011, "Normal offset shadows") raises it k t / cos(theta) above the plane along the
// sun's direction, which exceeds sqrt(2) r t tan(theta) for every tilt as long as
// k >= sqrt(2) r sin(theta): k = 1.5 texels covers all slopes with r = 1. The same offset moves a
// shadow's start on the ground by at most k t (peter-panning): 1.5 texels, 17 cm in the first
// cascade. Points in the air (no normal) move k t toward the sun.
// The float depth's rounding (range 200 km at 2^-24 relative: 1.2 cm) stays far below k t.
const float kNormalOffsetTexels = 1.5;

// A point's coordinates in a cascade's tile of the atlas: xy the atlas position, z the depth
// compared with the map's.
vec3 ShadowAtlasCoordinates(vec3 point, vec3 right, vec3 up, vec3 sun, vec4 origin, vec4 scale, vec2 tile) {
  vec3 light = vec3(dot(right, point), dot(up, point), dot(sun, point));
  vec2 p = (light.xy - origin.xy) * scale.x + 0.5;
  return vec3((p + tile) / float(kShadowAtlasTilesPerRow), (light.z - origin.w) * scale.y);
}

// Whether the cascades hold a point at this view depth (m): false beyond the last one and with
// shadows off. The point's depth is tested first, so that no branch depends on uniform values
// alone: lavapipe 22.x inlines such values into the shader and compiles it anew at every bind of
// its pipeline (a test of `cascades.x == 0` first made the opaque and transparent passes compile
// four shaders a frame).
bool InShadowCascades(float view_depth) {
  return !(view_depth > shadow.cascade_far_m[kShadowCascades - 1] || shadow.cascades.x == 0);
}

// A surface point's atlas coordinates in every cascade, moved by kNormalOffsetTexels texels of
// that cascade along its unit normal n. Each is an affine function of the point, so a vertex
// shader computes them and the rasterizer interpolates them exactly (perspective-correct), and a
// fragment only picks one (SunVisibilityFromCoordinates): on a CPU rasterizer the cascade's
// projection per fragment cost about as much as the filtered comparison itself. Only the normal
// offset is interpolated instead of computed from the normalized normal, a difference of the
// order of the normal's change across the triangle times 1.5 texels.
void SurfaceShadowCoordinates(vec3 relative_position, vec3 n, out vec3 coordinates[kShadowCascades]) {
  [[unroll]] for (int i = 0; i < kShadowCascades; ++i) {
    vec3 moved = relative_position + n * (kNormalOffsetTexels * shadow.cascade_scale[i].z);
    coordinates[i] = ShadowAtlasCoordinates(moved, shadow.cascade_right[i].xyz, shadow.cascade_up[i].xyz,
                                            shadow.cascade_toward_sun[i].xyz, shadow.cascade_origin[i],
                                            shadow.cascade_scale[i],
                                            vec2(i % kShadowAtlasTilesPerRow, i / kShadowAtlasTilesPerRow));
  }
}

// The sun's visibility in [0, 1] at a surface point, from its coordinates in every cascade
// (SurfaceShadowCoordinates): those of the cascade whose slice of view depth holds the point
// (each tile holds its slice with a margin for the filter and the offset: shadow_cascades.h,
// kShadowMarginTexels), or 1 beyond the cascades and with shadows off. Picked by comparisons and
// selects, with no dynamic indexing: a CPU rasterizer gathers a dynamically indexed value lane by
// lane.
float SunVisibilityFromCoordinates(vec3 relative_position, vec3 coordinates[kShadowCascades]) {
  if (kSunShadows == 0) return 1.0;
  float depth = dot(shadow.view_forward.xyz, relative_position);
  if (!InShadowCascades(depth)) return 1.0;
  vec3 p = coordinates[0];
  [[unroll]] for (int i = 1; i < kShadowCascades; ++i) {
    if (depth > shadow.cascade_far_m[i - 1]) p = coordinates[i];
  }
  return texture(shadow_map, p);
}

// A camera ray's points in the air, as the shadow map sees them, for looking up many points of one
// ray (the froxels' march, the marched per-pixel path). A point's atlas coordinates in a cascade are
// an affine function of its distance t along the ray, and so are its view depth and its distance
// from the sun's plane through the planet's centre; its squared distance from that centre is a
// quadratic in t. So each point costs a cascade's pick by selects and one multiply-add, not a
// projection.
struct ShadowRay {
  // Per cascade, the atlas coordinates of the ray's origin moved kNormalOffsetTexels texels of
  // the cascade toward its sun (points in the air have no normal), and their change per meter.
  vec3 start[kShadowCascades];
  vec3 slope[kShadowCascades];
  float depth_per_m;  // view depth per meter along the ray
  // |planet position|^2 - casters^2 = t (t + x) + y, and the planet position's component toward
  // the sun z + w t (SunVisibilityOnRay).
  vec4 above_casters;
};

// The change of ShadowAtlasCoordinates per meter along a direction.
vec3 ShadowAtlasDirection(vec3 direction, vec3 right, vec3 up, vec3 sun, vec4 scale) {
  vec2 p = vec2(dot(right, direction), dot(up, direction)) * scale.x;
  return vec3(p / float(kShadowAtlasTilesPerRow), dot(sun, direction) * scale.y);
}

// The shadow map's view of the ray from the camera along the unit vector `ray`;
// camera_planet_position: the camera relative to the planet's centre.
ShadowRay MakeShadowRay(vec3 ray, vec3 camera_planet_position) {
  ShadowRay r;
  [[unroll]] for (int i = 0; i < kShadowCascades; ++i) {
    vec3 right = shadow.cascade_right[i].xyz, up = shadow.cascade_up[i].xyz, sun = shadow.cascade_toward_sun[i].xyz;
    vec4 scale = shadow.cascade_scale[i];
    vec2 tile = vec2(i % kShadowAtlasTilesPerRow, i / kShadowAtlasTilesPerRow);
    r.start[i] = ShadowAtlasCoordinates(sun * (kNormalOffsetTexels * scale.z), right, up, sun,
                                        shadow.cascade_origin[i], scale, tile);
    r.slope[i] = ShadowAtlasDirection(ray, right, up, sun, scale);
  }
  r.depth_per_m = dot(shadow.view_forward.xyz, ray);
  // |c|^2 - casters^2 as a product: each factor is exact to float rounding, where the difference
  // of the two squares (about 4e13 m^2) would lose millions of m^2.
  float camera_r = length(camera_planet_position);
  r.above_casters = vec4(2.0 * dot(camera_planet_position, ray),
                         (camera_r - shadow.casters.x) * (camera_r + shadow.casters.x),
                         dot(camera_planet_position, shadow.toward_sun.xyz), dot(ray, shadow.toward_sun.xyz));
  return r;
}

// The sun's visibility in [0, 1] at the point t meters along a ShadowRay: 1 where the point is
// above every caster with the sun above its horizon (along the ray toward the sun the distance to
// the centre only grows there, r(t)^2 = r^2 + 2 t r mu_s + t^2, so no caster can lie on it),
// beyond the last cascade (100 km of view depth), or with shadows off; those read no shadow map.
// Else the cascade is picked as in SunVisibilityFromCoordinates.
float SunVisibilityOnRay(ShadowRay r, float t) {
  if (kSunShadows == 0) return 1.0;
  vec4 c = r.above_casters;
  if (t * (t + c.x) + c.y > 0.0 && c.z + c.w * t >= 0.0) return 1.0;
  float depth = t * r.depth_per_m;
  if (!InShadowCascades(depth)) return 1.0;
  vec3 start = r.start[0], slope = r.slope[0];
  [[unroll]] for (int i = 1; i < kShadowCascades; ++i) {
    if (depth > shadow.cascade_far_m[i - 1]) {
      start = r.start[i];
      slope = r.slope[i];
    }
  }
  return texture(shadow_map, start + t * slope);
}

#endif
