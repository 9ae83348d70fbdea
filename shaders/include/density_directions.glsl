// The direction grid of the scattering density pass, shared by its two halves: the incident
// radiance pass (which evaluates the radiance arriving from each direction once per (r, mu_s)) and
// the density pass (which convolves it with the phase functions for every (mu, nu)).
//
// Directions live in the sun frame: z is the local zenith and the sun lies in the xz-plane with
// positive x, omega_s = (sin theta_s, 0, mu_s). The incident radiance field is then symmetric under
// y -> -y, so only azimuths in [0, pi] are stored; the density pass adds the mirrored direction.
// The zenith range is split at the horizon (theta_h = pi - asin(R / r)) so that no cell straddles
// the discontinuity between sky and ground radiance. Each cell's weight is its exact solid angle,
// (cos theta_a - cos theta_b) * delta_phi, so the weights of a full sphere sum to 4 pi.
#ifndef AERIAL_DENSITY_DIRECTIONS_GLSL
#define AERIAL_DENSITY_DIRECTIONS_GLSL
#include "geometry.glsl"

int DensityDirectionCount() {
  return (atmosphere.density_directions.x + atmosphere.density_directions.y) *
         atmosphere.density_directions.z;
}

// The zenith angle of the cell boundary t in [0, 1] above the horizon: quadratic, so that cells
// are finest next to the horizon, where the incident radiance changes fastest (the sunlit layer
// above the Earth's shadow at twilight is a few degrees high). Against 16 equal cells, this took
// the twilight sky from 36% to 14% off and the low sun's from 32% to 15%, for the same cost; 32
// equal cells did less (26%, 23%) for twice the cost (aerial_bench_sky --grid quick).
float SkyZenithFromUnitRange(float t, float theta_h) {
  float s = 1.0 - t;
  return theta_h * (1.0 - s * s);
}

// The same below the horizon, from theta_h down to the nadir: quadratic, finest next to the
// horizon, where the inscatter along rays that meet the ground far away is brightest and falls
// fastest with depression. Against 8 equal cells this took the atmosphere's order 2 from 5.4% to
// 3.0% low (red, horizon view from the ground) at the same cost (README, "Accuracy against the
// physical sky").
float GroundZenithFromUnitRange(float t, float theta_h) {
  return theta_h + (PI - theta_h) * t * t;
}

// Direction `index` of the grid at radius r: xyz is the unit vector, w the cell's solid angle.
vec4 GetDensityDirection(float r, int index) {
  int theta_up = atmosphere.density_directions.x;
  int theta_down = atmosphere.density_directions.y;
  int phi_count = atmosphere.density_directions.z;
  int theta_index = index / phi_count;
  int phi_index = index % phi_count;
  float theta_h = HorizonZenithAngle(r);
  float theta_a;
  float theta_b;
  if (theta_index < theta_up) {
    theta_a = SkyZenithFromUnitRange(float(theta_index) / float(theta_up), theta_h);
    theta_b = SkyZenithFromUnitRange(float(theta_index + 1) / float(theta_up), theta_h);
  } else {
    int k = theta_index - theta_up;
    theta_a = GroundZenithFromUnitRange(float(k) / float(theta_down), theta_h);
    theta_b = GroundZenithFromUnitRange(float(k + 1) / float(theta_down), theta_h);
  }
  float d_phi = PI / float(phi_count);
  float theta = 0.5 * (theta_a + theta_b);
  float phi = (float(phi_index) + 0.5) * d_phi;
  vec3 direction = vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
  return vec4(direction, (cos(theta_a) - cos(theta_b)) * d_phi);
}

#endif
