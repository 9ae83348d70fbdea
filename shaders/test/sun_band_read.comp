#version 450
#extension GL_GOOGLE_include_directive : require
// Test shader: the sunlight's transmittance at each queried (r, mu_s), read from the sun band and
// computed over the disc directly (GetTransmittanceToSun), for comparison with the reference.
#include "transmittance.glsl"
layout(local_size_x = 64) in;
layout(set = 0, binding = 1) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 2) uniform sampler2D sun_band_texture;
layout(std430, set = 0, binding = 3) readonly buffer Queries { vec2 r_mu_s[]; };
// Per query: the band's value, then the direct one.
layout(std430, set = 0, binding = 4) writeonly buffer Results { vec4 transmittance[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= r_mu_s.length()) return;
  float r = r_mu_s[i].x;
  float mu_s = r_mu_s[i].y;
  transmittance[2 * i] =
      vec4(GetSunlightFromBand(transmittance_texture, sun_band_texture, r, mu_s, vec3(0.0)).direct, 0.0);
  transmittance[2 * i + 1] = vec4(GetTransmittanceToSun(transmittance_texture, r, mu_s), 0.0);
}
