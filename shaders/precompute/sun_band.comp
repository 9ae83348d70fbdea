#version 450
#extension GL_GOOGLE_include_directive : require
// Pass 1b: the sun band, GetTransmittanceToSun near each radius's horizon, for the single
// scattering passes (transmittance.glsl, "The sun band"), one texel per thread.
#include "transmittance.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 2) writeonly uniform image2D sun_band_image;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(sun_band_image);
  if (any(greaterThanEqual(texel, size))) return;
  float r;
  float mu_s;
  GetRMuSFromSunBandTextureUv(size, (vec2(texel) + 0.5) / vec2(size), r, mu_s);
  float visible = GetSunDiscVisibleFraction(GetSunElevationInDiscRadii(mu_s, GetHorizonCosine(r)));
  vec3 average = GetTransmittanceToSun(transmittance_texture, r, mu_s) / visible;
  imageStore(sun_band_image, texel, vec4(-log(max(average, vec3(1e-30))), 0.0));
}
