#version 450
#extension GL_GOOGLE_include_directive : require
// Pass 7 (orders >= 2): adds a quantity of order n, computed at the density resolution, to a final
// table, read at each target texel's own parameters (which resamples it to the target's grid);
// after the last order, with the series closed, the orders beyond it too (SumSeriesFromLastOrder).
// Two uses:
//  - The multiple scattering S_n. 4D: to the Rayleigh table, divided by the Rayleigh phase so that
//    render-time lookups multiply one phase back in (Bruneton 2017
//    "ComputeMultipleScatteringTexture": multiple scattering is nearly isotropic, and this keeps
//    the Rayleigh/Mie split without a third table). 3D: a table has no nu to divide by, so the
//    orders are summed in a table of their own (see sky_lookup.glsl).
//  - The scattering density J_n, summed into the multiple density table J_ms times its scale
//    (multiple_density_scale, for half floats), which render-time marches integrate along a
//    segment (sky_lookup.glsl).
//
// The division uses the texel's nominal nu (its place on the nu axis), not the nu it was clamped
// to. Near mu_s = 1 or mu = +-1 the allowed nu range collapses and every texel of a slice is
// clamped to nearly the same nu; dividing by P_R of that nu would store values whose nu dependence
// does not follow the axis, and a lookup that blends such texels with their neighbors (in mu_s or
// mu) is then off by up to 20% (measured at the horizon, sun zenith 30 degrees). Divided by the
// nominal phase, the stored values vary smoothly along the axis and the render-time product with
// P_R(nu) restores the radiance.
#include "scattering.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1) uniform sampler3D order_texture;           // order n
layout(set = 0, binding = 2) uniform sampler3D previous_order_texture;  // order n-1
layout(set = 0, binding = 3, rgba32f) uniform image3D accumulator;
layout(push_constant) uniform Step {
  ivec4 target_size;  // the accumulator's axes: r, mu, mu_s, nu
  int close_series;
  int divide_by_rayleigh_phase;
  int mu_axis;  // of the source and the accumulator: MU_AXIS_VIEW_ZENITH for the densities
  float scale;  // of what is added (J_ms's multiple_density_scale; 1 for the radiance)
} pass;

// A quantity of order n at (r, mu, mu_s, nu): the densities blended in mu_s like the render-time
// read of J_ms that they are summed into (GetDensityBlended), the radiance linearly.
vec3 ReadOrder(sampler3D order_texture, float r, float mu, float mu_s, float nu,
               bool ray_r_mu_intersects_ground) {
  if (pass.mu_axis == MU_AXIS_VIEW_ZENITH) {
    return GetDensityOfOrder(order_texture, AERIAL_ATMOSPHERE.density_size, true, r, mu, mu_s, nu,
                             ray_r_mu_intersects_ground);
  }
  return GetScatteringClampedNu(order_texture, AERIAL_ATMOSPHERE.density_size, pass.mu_axis, r, mu, mu_s,
                                nu, ray_r_mu_intersects_ground);
}

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (!IsScatteringTexel(pass.target_size, texel)) return;
  float r, mu, mu_s, nu;
  bool ray_r_mu_intersects_ground;
  GetRMuMuSNuFromScatteringTexel(pass.target_size, pass.mu_axis, texel, r, mu, mu_s, nu,
                                 ray_r_mu_intersects_ground);
  vec3 value = ReadOrder(order_texture, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  if (pass.close_series != 0) {
    value = SumSeriesFromLastOrder(
        value, ReadOrder(previous_order_texture, r, mu, mu_s, nu, ray_r_mu_intersects_ground));
  }
  if (pass.divide_by_rayleigh_phase != 0)
    value /= RayleighPhaseFunction(GetScatteringTexelNominalNu(pass.target_size, texel));
  imageStore(accumulator, texel, imageLoad(accumulator, texel) + vec4(value * pass.scale, 0.0));
}
