#version 450
// Opaque geometry's lit surface radiance (opaque.vert) without aerial perspective, and its
// distance from the camera: what Renderer::ReadSurface draws on request, for checks against a
// reference that applies its own aerial perspective. Frames use opaque.frag.
layout(location = 0) in vec3 relative_position;
layout(location = 1) in vec3 surface_radiance;
layout(location = 0) out vec4 radiance_and_distance;

void main() { radiance_and_distance = vec4(surface_radiance, length(relative_position)); }
