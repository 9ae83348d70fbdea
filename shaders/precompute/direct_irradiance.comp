#version 450
#extension GL_GOOGLE_include_directive : require
// Pass 2: direct sun irradiance on the ground, E_0(r, mu_s): the order-0 light that the ground
// reflects into the order-2 scattering density. Not added to the irradiance table (it is computed
// exactly from the transmittance table at render time).
#include "irradiance.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 2) writeonly uniform image2D delta_irradiance_image;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, AERIAL_ATMOSPHERE.irradiance_size.xy))) return;
  float r;
  float mu_s;
  GetRMuSFromIrradianceTextureUv((vec2(texel) + 0.5) / vec2(AERIAL_ATMOSPHERE.irradiance_size.xy), r, mu_s);
  imageStore(delta_irradiance_image, texel,
             vec4(ComputeDirectIrradiance(transmittance_texture, r, mu_s), 1.0));
}
