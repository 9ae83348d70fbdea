#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates the render-time table lookups for a batch of (camera, view ray, sun) queries: what
// `aerial probe` prints and what the table-vs-reference tests compare. One thread per query.
#include "sky_lookup.glsl"
layout(local_size_x = 32) in;
layout(set = 0, binding = 1) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 2) uniform sampler2D irradiance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler3D multiple_density_texture;

struct ProbeQuery {
  vec4 geometry;  // r, mu, mu_s, nu
  vec4 segment;   // x: distance along the view ray for the *_to_point values
};
struct ProbeResult {
  vec4 sky_radiance;
  vec4 transmittance;
  vec4 sun_irradiance;
  vec4 sky_irradiance;
  vec4 solar_radiance;
  vec4 radiance_to_point;
  vec4 transmittance_to_point;
  vec4 rayleigh;  // table values without phase, to the boundary
  vec4 mie;
};
layout(std430, set = 0, binding = 7) readonly buffer Queries { ProbeQuery queries[]; };
layout(std430, set = 0, binding = 8) writeonly buffer Results { ProbeResult results[]; };
layout(push_constant) uniform Batch { int count; } batch;

void main() {
  int index = int(gl_GlobalInvocationID.x);
  if (index >= batch.count) return;
  float r = queries[index].geometry.x;
  float mu = queries[index].geometry.y;
  float mu_s = queries[index].geometry.z;
  float nu = queries[index].geometry.w;
  Inscatter sky = GetSkyInscatter(transmittance_texture, rayleigh_texture, mie_texture,
                                  multiple_texture, r, mu, mu_s, nu);
  Inscatter segment =
      GetSkyInscatterToPoint(transmittance_texture, multiple_density_texture, r, mu, mu_s, nu,
                             queries[index].segment.x);
  ProbeResult result;
  result.sky_radiance = vec4(ApplyPhaseFunctions(sky, nu), 0.0);
  result.transmittance = vec4(sky.transmittance, 0.0);
  result.sun_irradiance = vec4(ComputeDirectIrradiance(transmittance_texture, r, mu_s), 0.0);
  result.sky_irradiance = vec4(GetIrradiance(irradiance_texture, r, mu_s), 0.0);
  result.solar_radiance = vec4(GetSolarRadiance(), 0.0);
  result.radiance_to_point = vec4(ApplyPhaseFunctions(segment, nu), 0.0);
  result.transmittance_to_point = vec4(segment.transmittance, 0.0);
  result.rayleigh = vec4(sky.rayleigh, 0.0);
  result.mie = vec4(sky.mie, 0.0);
  results[index] = result;
}
