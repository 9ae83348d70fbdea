#version 450
#extension GL_GOOGLE_include_directive : require
// Pass 4a (orders >= 2): the radiance of order n-1 arriving at each (r, mu_s) of the density
// table from each direction of the density grid (density_directions.glsl), ground reflection of
// the order n-2 irradiance included (Bruneton 2017 "ComputeScatteringDensity", inner loop).
//
// This is where the speed-up over Bruneton's density pass comes from: the incident radiance at a
// point depends on (r, mu_s) and the direction relative to the sun, not on the view direction, so
// it is evaluated once here instead of once for each of the MU * NU texels sharing (r, mu_s).
#include "density_directions.glsl"
#include "irradiance.glsl"
layout(local_size_x = 64) in;
layout(set = 0, binding = 1) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 2) uniform sampler3D single_rayleigh_texture;
layout(set = 0, binding = 3) uniform sampler3D single_mie_texture;
layout(set = 0, binding = 4) uniform sampler3D multiple_scattering_texture;
layout(set = 0, binding = 5) uniform sampler2D delta_irradiance_texture;
// [r][mu_s][direction]: incident radiance times the cell's solid angle.
layout(std430, set = 0, binding = 6) writeonly buffer IncidentRadiance { vec4 weighted_radiance[]; };
// [r][direction]: the direction and its solid angle.
layout(std430, set = 0, binding = 7) writeonly buffer Directions { vec4 directions[]; };
layout(push_constant) uniform Order { int order; } pass;  // order of the density being computed

void main() {
  int direction_count = DensityDirectionCount();
  int direction_index = int(gl_GlobalInvocationID.x);
  int mu_s_index = int(gl_GlobalInvocationID.y);
  int r_index = int(gl_GlobalInvocationID.z);
  if (direction_index >= direction_count) return;
  ivec4 size = AERIAL_ATMOSPHERE.density_size;
  float r = GetRFromScatteringUR(size, (float(r_index) + 0.5) / float(size.x));
  float mu_s = GetMuSFromScatteringUMuS(size, (float(mu_s_index) + 0.5) / float(size.z));
  vec4 omega_i = GetDensityDirection(r, direction_index);
  vec3 omega_s = vec3(sqrt(max(1.0 - mu_s * mu_s, 0.0)), 0.0, mu_s);
  float nu_i = dot(omega_i.xyz, omega_s);
  bool hits_ground = RayIntersectsGround(r, omega_i.z);
  vec3 radiance = GetScatteringOfOrder(single_rayleigh_texture, single_mie_texture,
                                       multiple_scattering_texture, r, omega_i.z, mu_s, nu_i,
                                       hits_ground, pass.order - 1);
  if (hits_ground) {
    // Light of order n-2 reflected by the Lambertian ground at q = x + d omega_i.
    float d = DistanceToBottomAtmosphereBoundary(r, omega_i.z);
    vec3 ground_normal = normalize(vec3(0.0, 0.0, r) + omega_i.xyz * d);
    vec3 ground_irradiance = GetIrradiance(delta_irradiance_texture, AERIAL_ATMOSPHERE.bottom_radius,
                                           dot(ground_normal, omega_s));
    radiance += GetTransmittance(transmittance_texture, r, omega_i.z, d, true) *
                AERIAL_ATMOSPHERE.ground_albedo.rgb * (1.0 / PI) * ground_irradiance;
  }
  int slot = (r_index * size.z + mu_s_index) * direction_count + direction_index;
  weighted_radiance[slot] = vec4(radiance * omega_i.w, 0.0);
  if (mu_s_index == 0) directions[r_index * direction_count + direction_index] = omega_i;
}
