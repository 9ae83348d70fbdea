#version 450
#extension GL_GOOGLE_include_directive : require
// Pass 5: ground irradiance from the sky radiance of order n, stored as the delta for the next
// order's ground reflection and added to the irradiance table; after the last order N, with the
// series closed, the orders beyond it too (SumSeriesFromLastOrder with E_N / E_{N-1}).
#include "irradiance.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1) uniform sampler3D single_rayleigh_texture;
layout(set = 0, binding = 2) uniform sampler3D single_mie_texture;
layout(set = 0, binding = 3) uniform sampler3D multiple_scattering_texture;
layout(set = 0, binding = 4) uniform sampler2D previous_delta_irradiance;  // from order n-1
layout(set = 0, binding = 5) writeonly uniform image2D delta_irradiance_image;
layout(set = 0, binding = 6, rgba32f) uniform image2D irradiance_accumulator;
layout(set = 0, binding = 7) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 8) uniform sampler2D sun_band_texture;
layout(push_constant) uniform Order {
  int order;  // of the radiance integrated
  int close_series;
} pass;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, AERIAL_ATMOSPHERE.irradiance_size.xy))) return;
  float r;
  float mu_s;
  GetRMuSFromIrradianceTextureUv((vec2(texel) + 0.5) / vec2(AERIAL_ATMOSPHERE.irradiance_size.xy), r, mu_s);
  vec3 irradiance = ComputeIndirectIrradiance(transmittance_texture, sun_band_texture,
                                              single_rayleigh_texture, single_mie_texture,
                                              multiple_scattering_texture, r, mu_s, pass.order);
  imageStore(delta_irradiance_image, texel, vec4(irradiance, 0.0));
  if (pass.close_series != 0)
    irradiance = SumSeriesFromLastOrder(irradiance, texelFetch(previous_delta_irradiance, texel, 0).rgb);
  imageStore(irradiance_accumulator, texel,
             imageLoad(irradiance_accumulator, texel) + vec4(irradiance, 0.0));
}
