#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque geometry: vertices are made camera-relative before projection (float precision).
#include "frame.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 albedo;
layout(location = 3) in float opacity;
layout(location = 0) out vec3 relative_position;
layout(location = 1) out vec3 surface_normal;
layout(location = 2) out vec3 surface_albedo;

void main() {
  relative_position = position - frame.camera_scene_position.xyz;
  surface_normal = normal;
  surface_albedo = albedo;
  gl_Position = frame.view_projection * vec4(relative_position, 1.0);
}
