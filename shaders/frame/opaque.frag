#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque geometry seen through the air, into one color target (opaque_fragment.glsl).
#include "opaque_fragment.glsl"
layout(location = 0) out vec4 color;

void main() { color = GetFragmentRadiance(GetFragmentSunVisibility()); }
