#version 450
#extension GL_GOOGLE_include_directive : require
// Pass 1: transmittance to the top of the atmosphere, stored as the optical depth tau(r, mu)
// (transmittance.glsl explains why), one texel per thread.
#include "transmittance.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1) writeonly uniform image2D transmittance_image;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, AERIAL_ATMOSPHERE.transmittance_size.xy))) return;
  float r;
  float mu;
  GetRMuFromTransmittanceTextureUv((vec2(texel) + 0.5) / vec2(AERIAL_ATMOSPHERE.transmittance_size.xy),
                                   r, mu);
  imageStore(transmittance_image, texel, vec4(ComputeOpticalDepthToTopAtmosphereBoundary(r, mu), 1.0));
}
