#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque geometry seen through the air, its sun visibility also written to a second color target
// for the frames that follow while nothing moves (opaque_fragment.glsl).
#include "opaque_fragment.glsl"
layout(location = 0) out vec4 color;
layout(location = 1) out float sun_visibility_target;

void main() {
  float sun_visibility = GetFragmentSunVisibility();
  sun_visibility_target = sun_visibility;
  color = GetFragmentRadiance(sun_visibility);
}
