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
#include "definitions.glsl"

int DensityDirectionCount() {
  return (atmosphere.density_directions.x + atmosphere.density_directions.y) *
         atmosphere.density_directions.z;
}

// Direction `index` of the grid at radius r: xyz is the unit vector, w the cell's solid angle.
vec4 GetDensityDirection(float r, int index) {
  int theta_up = atmosphere.density_directions.x;
  int theta_down = atmosphere.density_directions.y;
  int phi_count = atmosphere.density_directions.z;
  int theta_index = index / phi_count;
  int phi_index = index % phi_count;
  float theta_h = PI - asin(clamp(atmosphere.bottom_radius / r, 0.0, 1.0));
  float theta_a;
  float theta_b;
  if (theta_index < theta_up) {
    theta_a = theta_h * float(theta_index) / float(theta_up);
    theta_b = theta_h * float(theta_index + 1) / float(theta_up);
  } else {
    int k = theta_index - theta_up;
    theta_a = theta_h + (PI - theta_h) * float(k) / float(theta_down);
    theta_b = theta_h + (PI - theta_h) * float(k + 1) / float(theta_down);
  }
  float d_phi = PI / float(phi_count);
  float theta = 0.5 * (theta_a + theta_b);
  float phi = (float(phi_index) + 0.5) * d_phi;
  vec3 direction = vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
  return vec4(direction, (cos(theta_a) - cos(theta_b)) * d_phi);
}

#endif
