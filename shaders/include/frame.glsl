// Per-frame camera and sun, shared by the froxel, raster and composite passes. Positions in the
// shaders are camera-relative world vectors (x east, y north, z up, meters), which keeps them
// precise in float; the atmosphere lookups use the camera's planet-centered position.
#ifndef AERIAL_FRAME_GLSL
#define AERIAL_FRAME_GLSL
#include "definitions.glsl"

// Where the aerial perspective of a surface comes from: a specialization constant, so the paths
// not taken are compiled out (a CPU rasterizer would run them all).
const int AERIAL_FROXELS = 0;           // the froxel volume: what a caller embedding aerial wants
const int AERIAL_MARCHED = 1;           // per pixel, marched along the pixel's ray (the reference)
const int AERIAL_TABLE_DIFFERENCE = 2;  // per pixel, two table reads (Bruneton 2017's demo)
layout(constant_id = 0) const int kAerialPerPixel = 0;

// Mirrored by aerial::FrameUniforms (aerial/shader_abi/frame_block.h); tests/uniform_layout_test.cpp
// checks every member's offset against the compiler's layout.
struct FrameParameters {
  mat4 view_projection;          // camera-relative world -> clip (reversed Z, infinite far)
  mat4 inverse_view_projection;  // clip -> camera-relative world
  vec4 camera_scene_position;    // xyz: camera in the scene frame (to make vertices relative)
  vec4 camera_planet_position;   // xyz: camera relative to the planet center
  vec4 sun_direction;            // xyz: unit vector toward the sun
  ivec4 froxel_size;             // x, y, z: froxel grid (w unused)
  vec4 froxel_depth;             // x: far distance of the last slice (m)
  vec4 viewport;                 // x, y: size in pixels
  vec4 froxel_rows;              // the froxel rows' placement (froxel_axes.glsl)
  vec4 froxel_columns;           // the froxel columns' placement
};
layout(std140, set = 0, binding = 1) uniform FrameBlock {
  FrameParameters parameters[1];  // at AERIAL_BLOCK_INDEX (definitions.glsl)
} frame_block;
#define AERIAL_FRAME frame_block.parameters[AERIAL_BLOCK_INDEX]

// Unit view ray (camera-relative world) through a point of the screen, uv in [0,1]^2.
vec3 ViewRayFromScreen(vec2 uv) {
  vec4 clip = vec4(uv * 2.0 - 1.0, 0.5, 1.0);
  vec4 world = AERIAL_FRAME.inverse_view_projection * clip;
  return normalize(world.xyz / world.w);
}

// The distance from the camera to the point a pixel's reversed-Z depth value stands for.
float DistanceFromDepth(vec2 uv, float depth) {
  vec4 world = AERIAL_FRAME.inverse_view_projection * vec4(uv * 2.0 - 1.0, depth, 1.0);
  return length(world.xyz / world.w);
}

// The (r, mu, mu_s, nu) of a ray from the camera, for the table lookups.
void GetCameraRayParameters(vec3 ray, out float r, out float mu, out float mu_s, out float nu) {
  vec3 x = AERIAL_FRAME.camera_planet_position.xyz;
  r = length(x);
  mu = dot(x, ray) / r;
  mu_s = dot(x, AERIAL_FRAME.sun_direction.xyz) / r;
  nu = dot(ray, AERIAL_FRAME.sun_direction.xyz);
}

#endif
