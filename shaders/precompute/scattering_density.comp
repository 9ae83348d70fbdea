#version 450
#extension GL_GOOGLE_include_directive : require
// Pass 4b (orders >= 2): the scattering density J(r, mu, mu_s, nu) of order n (Bruneton 2008
// eq. 7): the incident radiance of pass 4a convolved with each species' phase function and scaled
// by its scattering coefficient. One workgroup shares one (r, mu_s, nu) and stages the incident
// radiance in shared memory; the threads differ only in mu. The invocation's x is the mu index:
// CPU implementations (lavapipe) vectorize along local x, so x must be the wide dimension.
//
// The discrete phase weights are renormalized to sum to 1 (the phase functions' exact integral):
// with a finite direction grid Mie's forward peak would otherwise gain or lose energy depending on
// where it falls between grid directions.
#include "density_directions.glsl"
#include "mappings.glsl"
#include "phase.glsl"
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 1) readonly buffer IncidentRadiance { vec4 weighted_radiance[]; };
layout(std430, set = 0, binding = 2) readonly buffer Directions { vec4 directions[]; };
layout(set = 0, binding = 3) writeonly uniform image3D scattering_density_image;

const int kMaxDirections = 1024;
const int kMaxRings = 256;
shared vec3 shared_radiance[kMaxDirections];
shared vec4 shared_direction[kMaxDirections];
// 3D tables: per zenith ring of the grid, rgb = sum of L dw over the full circle, a = its solid
// angle (both halves: the radiance field is mirror-symmetric).
shared vec4 shared_ring[kMaxRings];

// 4D: J for the view direction omega (sun frame), summing the grid and its mirror image.
void ConvolveWithPhases(vec3 omega, int direction_count, out vec3 rayleigh, out vec3 mie) {
  float g = AERIAL_ATMOSPHERE.mie_phase_g;
  vec3 omega_mirror = vec3(omega.x, -omega.y, omega.z);
  vec3 rayleigh_sum = vec3(0.0);
  vec3 mie_sum = vec3(0.0);
  float rayleigh_norm = 0.0;
  float mie_norm = 0.0;
  for (int k = 0; k < direction_count; ++k) {
    vec4 omega_i = shared_direction[k];  // w: the cell's solid angle
    float c0 = dot(omega, omega_i.xyz);
    float c1 = dot(omega_mirror, omega_i.xyz);
    float rayleigh_phase = RayleighPhaseFunction(c0) + RayleighPhaseFunction(c1);
    float mie_phase = MiePhaseFunction(g, c0) + MiePhaseFunction(g, c1);
    rayleigh_sum += shared_radiance[k] * rayleigh_phase;
    mie_sum += shared_radiance[k] * mie_phase;
    rayleigh_norm += omega_i.w * rayleigh_phase;
    mie_norm += omega_i.w * mie_phase;
  }
  rayleigh = rayleigh_sum / rayleigh_norm;
  mie = mie_sum / mie_norm;
}

// 3D (Elek 2009): J averaged over the view azimuth around the zenith, since the table has no nu.
// The average of P(omega . omega_i) over the azimuth of omega depends only on the two zenith
// angles, so the grid collapses to its zenith rings and each ring needs one averaged phase,
// P_bar(mu, mu_i) = 1/pi integral_0^pi P(mu mu_i + sin sin_i cos psi) dpsi (midpoint rule).
void ConvolveWithAveragedPhases(float mu, int ring_count, out vec3 rayleigh, out vec3 mie) {
  const int kAzimuths = 16;
  float g = AERIAL_ATMOSPHERE.mie_phase_g;
  float sin_theta = sqrt(max(1.0 - mu * mu, 0.0));
  vec3 rayleigh_sum = vec3(0.0);
  vec3 mie_sum = vec3(0.0);
  float rayleigh_norm = 0.0;
  float mie_norm = 0.0;
  for (int m = 0; m < ring_count; ++m) {
    float mu_i = shared_direction[m * AERIAL_ATMOSPHERE.density_directions.z].z;
    float sin_theta_i = sqrt(max(1.0 - mu_i * mu_i, 0.0));
    float rayleigh_phase = 0.0;
    float mie_phase = 0.0;
    for (int j = 0; j < kAzimuths; ++j) {
      float c = mu * mu_i + sin_theta * sin_theta_i * cos((float(j) + 0.5) * PI / float(kAzimuths));
      rayleigh_phase += RayleighPhaseFunction(c);
      mie_phase += MiePhaseFunction(g, c);
    }
    rayleigh_sum += shared_ring[m].rgb * rayleigh_phase;
    mie_sum += shared_ring[m].rgb * mie_phase;
    rayleigh_norm += shared_ring[m].a * rayleigh_phase;
    mie_norm += shared_ring[m].a * mie_phase;
  }
  rayleigh = rayleigh_sum / rayleigh_norm;
  mie = mie_sum / mie_norm;
}

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID.y, gl_GlobalInvocationID.x, gl_GlobalInvocationID.z);
  int direction_count = DensityDirectionCount();
  int phi_count = AERIAL_ATMOSPHERE.density_directions.z;
  int ring_count = direction_count / phi_count;
  bool drop_nu = AERIAL_ATMOSPHERE.density_size.w == 1;
  int mu_s_size = AERIAL_ATMOSPHERE.density_size.z;
  int mu_s_index = texel.x % mu_s_size;
  int first = (texel.z * mu_s_size + mu_s_index) * direction_count;
  for (int k = int(gl_LocalInvocationIndex); k < direction_count; k += 64) {
    shared_radiance[k] = weighted_radiance[first + k].rgb;
    shared_direction[k] = directions[texel.z * direction_count + k];
  }
  barrier();
  if (drop_nu) {
    for (int m = int(gl_LocalInvocationIndex); m < ring_count; m += 64) {
      vec4 ring = vec4(0.0);
      for (int j = 0; j < phi_count; ++j) {
        int k = m * phi_count + j;
        ring += vec4(shared_radiance[k], shared_direction[k].w);
      }
      shared_ring[m] = 2.0 * ring;
    }
    barrier();
  }
  if (!IsScatteringTexel(AERIAL_ATMOSPHERE.density_size, texel)) return;

  float r, mu, mu_s, nu;
  bool ray_r_mu_intersects_ground;
  GetRMuMuSNuFromScatteringTexel(AERIAL_ATMOSPHERE.density_size, MU_AXIS_VIEW_ZENITH, texel, r, mu,
                                 mu_s, nu, ray_r_mu_intersects_ground);
  vec3 rayleigh;
  vec3 mie;
  if (drop_nu) {
    ConvolveWithAveragedPhases(mu, ring_count, rayleigh, mie);
  } else {
    // View direction in the sun frame (sun at azimuth 0).
    float sin_theta = sqrt(max(1.0 - mu * mu, 0.0));
    float sin_theta_s = sqrt(max(1.0 - mu_s * mu_s, 0.0));
    float cos_phi = sin_theta * sin_theta_s > 0.0
                        ? clamp((nu - mu * mu_s) / (sin_theta * sin_theta_s), -1.0, 1.0)
                        : 1.0;
    vec3 omega =
        vec3(sin_theta * cos_phi, sin_theta * sqrt(max(1.0 - cos_phi * cos_phi, 0.0)), mu);
    ConvolveWithPhases(omega, direction_count, rayleigh, mie);
  }
  float altitude = r - AERIAL_ATMOSPHERE.bottom_radius;
  vec3 density =
      AERIAL_ATMOSPHERE.rayleigh_scattering.rgb * GetProfileDensity(AERIAL_ATMOSPHERE.rayleigh_density, altitude) *
          rayleigh +
      AERIAL_ATMOSPHERE.mie_scattering.rgb * GetProfileDensity(AERIAL_ATMOSPHERE.mie_density, altitude) * mie;
  imageStore(scattering_density_image, texel, vec4(density, 0.0));
}
