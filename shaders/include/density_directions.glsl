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
  return (AERIAL_ATMOSPHERE.density_directions.x + AERIAL_ATMOSPHERE.density_directions.y) *
         AERIAL_ATMOSPHERE.density_directions.z;
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
// 3.0% low (red, horizon view from the ground) at the same cost (docs/accuracy.md, "Accuracy against the
// physical sky").
float GroundZenithFromUnitRange(float t, float theta_h) {
  return theta_h + (PI - theta_h) * t * t;
}

float ZenithFromUnitRange(bool ground, float t, float theta_h) {
  return ground ? GroundZenithFromUnitRange(t, theta_h) : SkyZenithFromUnitRange(t, theta_h);
}

// The node of the zenith cell [t_a, t_b] (zenith angles [theta_a, theta_b]): the direction whose
// distance to the atmosphere's boundary (the ground, or the top) is that distance's mean over the
// cell's solid angle. The one-node rule is then exact for radiance proportional to the path length,
// as in optically thin air, which is the shape of the incident radiance: it grows as 1 / |mu| away
// from the horizon and as the square root of the angle next to it, a convex curve whose midpoint in
// theta is too low. Order 2's density 5 km up (Rayleigh, black ground; sun zenith 0-80 degrees,
// four views; against a fine Gauss-Legendre grid in numpy): the midpoint put it 1.9-3.6% low from
// below the horizon and 0.6-0.8% low from above, this node -0.1..+0.9% and -0.3..+0.3%.
// The mean is taken by Gauss-Legendre in t, where d mu = sin(theta) (d theta / dt) dt is smooth:
// both mappings are quadratic in the distance u of t from the horizon's end, so d theta ~ u dt.
float CellNodeZenith(float r, bool ground, float t_a, float t_b, float theta_a, float theta_b,
                     float theta_h) {
  const int kNodes = 4;
  const float kAbscissa[kNodes] = float[](-0.8611363, -0.3399810, 0.3399810, 0.8611363);
  const float kWeight[kNodes] = float[](0.3478548, 0.6521452, 0.6521452, 0.3478548);
  float distance_sum = 0.0;
  float weight_sum = 0.0;
  for (int i = 0; i < kNodes; ++i) {
    float t = 0.5 * (t_a + t_b) + 0.5 * (t_b - t_a) * kAbscissa[i];
    float theta = ZenithFromUnitRange(ground, t, theta_h);
    float weight = kWeight[i] * sin(theta) * (ground ? t : 1.0 - t);
    float mu = cos(theta);
    distance_sum += weight * (ground ? DistanceToBottomAtmosphereBoundary(r, mu)
                                     : DistanceToTopAtmosphereBoundary(r, mu));
    weight_sum += weight;
  }
  float d = distance_sum / weight_sum;
  // The boundary at radius b is met at distance d where b^2 = r^2 + d^2 + 2 r d mu. The distance is
  // monotonic in mu across the cell, so the node lies inside it up to rounding.
  float b = ground ? AERIAL_ATMOSPHERE.bottom_radius : AERIAL_ATMOSPHERE.top_radius;
  float mu = ClampCosine(((b - r) * (b + r) - d * d) / (2.0 * r * d));
  return clamp(acos(mu), theta_a, theta_b);
}

// Direction `index` of the grid at radius r: xyz is the unit vector, w the cell's solid angle.
vec4 GetDensityDirection(float r, int index) {
  int theta_up = AERIAL_ATMOSPHERE.density_directions.x;
  int theta_down = AERIAL_ATMOSPHERE.density_directions.y;
  int phi_count = AERIAL_ATMOSPHERE.density_directions.z;
  int theta_index = index / phi_count;
  int phi_index = index % phi_count;
  float theta_h = HorizonZenithAngle(r);
  bool ground = theta_index >= theta_up;
  int cells = ground ? theta_down : theta_up;
  int cell = ground ? theta_index - theta_up : theta_index;
  float t_a = float(cell) / float(cells);
  float t_b = float(cell + 1) / float(cells);
  float theta_a = ZenithFromUnitRange(ground, t_a, theta_h);
  float theta_b = ZenithFromUnitRange(ground, t_b, theta_h);
  float theta = CellNodeZenith(r, ground, t_a, t_b, theta_a, theta_b, theta_h);
  float d_phi = PI / float(phi_count);
  float phi = (float(phi_index) + 0.5) * d_phi;
  vec3 direction = vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
  return vec4(direction, (cos(theta_a) - cos(theta_b)) * d_phi);
}

#endif
