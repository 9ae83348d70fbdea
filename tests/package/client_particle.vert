#version 450
#extension GL_GOOGLE_include_directive : require
// A client's own vertex shader for particles or glass: aerial's froxels read per vertex
// (GetAerialPerspectiveAtVertex, installed aerial_perspective.glsl); the phases stay per pixel.
#include "aerial_perspective.glsl"
layout(set = 0, binding = 4) uniform sampler3D client_rayleigh;
layout(set = 0, binding = 5) uniform sampler3D client_mie;
layout(set = 0, binding = 6) uniform sampler3D client_transmittance;
layout(location = 0) in vec3 scene_position;
layout(location = 0) out vec3 vertex_rayleigh;
layout(location = 1) out vec3 vertex_mie;
layout(location = 2) out vec3 vertex_transmittance;

void main() {
  vec3 relative_position = scene_position - AERIAL_FRAME.camera_scene_position.xyz;
  gl_Position = AERIAL_FRAME.view_projection * vec4(relative_position, 1.0);
  Inscatter segment = GetAerialPerspectiveAtVertex(client_rayleigh, client_mie, client_transmittance, gl_Position,
                                                   length(relative_position));
  vertex_rayleigh = segment.rayleigh;
  vertex_mie = segment.mie;
  vertex_transmittance = segment.transmittance;
}
