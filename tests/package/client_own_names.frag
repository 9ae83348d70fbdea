#version 450
#extension GL_GOOGLE_include_directive : require
// A client's shader that calls its own things `frame` and `atmosphere` (a block member, a local),
// with aerial's installed GLSL included before them: the includes' macros all start with AERIAL_,
// so they take no name of the client's. run.sh compiles it against the installed include directory.
#include "aerial_perspective.glsl"
struct Frame {
  vec2 size;
  float exposure;
};
layout(set = 1, binding = 0) uniform ClientBlock {
  Frame frame;
};
layout(set = 0, binding = 4) uniform sampler3D client_rayleigh;
layout(set = 0, binding = 5) uniform sampler3D client_mie;
layout(set = 0, binding = 6) uniform sampler3D client_transmittance;
layout(location = 0) in vec3 relative_position;
layout(location = 1) in vec3 lit_radiance;
layout(location = 0) out vec4 color;

void main() {
  Inscatter atmosphere = GetAerialPerspective(client_rayleigh, client_mie, client_transmittance,
                                              gl_FragCoord.xy / frame.size, length(relative_position));
  color = vec4(frame.exposure * ApplyAerialPerspective(lit_radiance, atmosphere, ViewSunCosine(relative_position)),
               1.0);
}
