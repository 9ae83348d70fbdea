#version 450
#extension GL_GOOGLE_include_directive : require
// Pass 5 (orders >= 2): ground irradiance from the sky radiance of order n-1, stored as the delta
// for the next order's ground reflection and added to the irradiance table.
#include "irradiance.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1) uniform sampler3D single_rayleigh_texture;
layout(set = 0, binding = 2) uniform sampler3D single_mie_texture;
layout(set = 0, binding = 3) uniform sampler3D multiple_scattering_texture;
layout(set = 0, binding = 4) writeonly uniform image2D delta_irradiance_image;
layout(set = 0, binding = 5, rgba32f) uniform image2D irradiance_accumulator;
layout(push_constant) uniform Order { int order; } pass;  // order of the radiance integrated

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, atmosphere.irradiance_size.xy))) return;
  float r;
  float mu_s;
  GetRMuSFromIrradianceTextureUv((vec2(texel) + 0.5) / vec2(atmosphere.irradiance_size.xy), r, mu_s);
  vec3 irradiance = ComputeIndirectIrradiance(single_rayleigh_texture, single_mie_texture,
                                              multiple_scattering_texture, r, mu_s, pass.order);
  imageStore(delta_irradiance_image, texel, vec4(irradiance, 0.0));
  imageStore(irradiance_accumulator, texel,
             imageLoad(irradiance_accumulator, texel) + vec4(irradiance, 0.0));
}
