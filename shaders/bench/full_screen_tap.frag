#version 450
// The benchmarks' unit of cost (docs/design.md, "Conventions"): a full-screen pass whose fragments
// each make one trilinear tap of a 3D texture, at a depth that varies across the screen so that
// neighbouring pixels do not read the same texels.
layout(set = 0, binding = 0) uniform sampler3D volume;
layout(push_constant) uniform Push { vec2 target_size; } push;
layout(location = 0) out vec4 color;

void main() {
  vec2 uv = gl_FragCoord.xy / push.target_size;
  color = vec4(textureLod(volume, vec3(uv, fract(uv.x * 7.0 + uv.y * 3.0)), 0.0).rgb, 1.0);
}
