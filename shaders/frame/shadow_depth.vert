#version 450
// The sun's shadow map, one cascade (src/aerial/render/shadow_map.h): the opaque casters' depth
// as the sun sees them, through the cascade's orthographic projection. Vertices are made
// camera-relative first, as the frame's shaders do before their own lookups (shadow.glsl), so
// both round the same float positions. Depth only: the pipeline has no fragment shader.
layout(push_constant) uniform Cascade {
  mat4 clip_from_relative;     // camera-relative world -> the cascade's clip space
  vec4 camera_scene_position;  // xyz: the camera the projection is relative to
} cascade;
layout(location = 0) in vec3 position;

void main() {
  gl_Position = cascade.clip_from_relative * vec4(position - cascade.camera_scene_position.xyz, 1.0);
}
