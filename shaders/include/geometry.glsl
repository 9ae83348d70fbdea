// Ray geometry inside a spherical shell (Bruneton 2017, functions.glsl section "Distance to the top
// and bottom atmosphere boundaries"). A ray starts at radius r with cos(view zenith) = mu.
//
// Precision near the horizon. The textbook discriminant r^2 (mu^2 - 1) + R^2 subtracts numbers of
// order 4e13 m^2 that cancel at the horizon; in float32 that leaves an absolute error of ~1e7 m^2,
// i.e. kilometers in the distance to the ground, and the horizon texels of the tables then land on
// the wrong texel or the wrong half of the mu axis: the classic horizon line. Writing r^2 - R^2 as
// (r - R)(r + R), where r - R is exact (Sterbenz), brings the error down to that of rho^2 itself.
#ifndef AERIAL_GEOMETRY_GLSL
#define AERIAL_GEOMETRY_GLSL
#include "definitions.glsl"

// r^2 - R_bottom^2 = rho^2, the squared distance to the horizon, without cancellation.
float SquaredHorizonDistance(float r) {
  return max((r - AERIAL_ATMOSPHERE.bottom_radius) * (r + AERIAL_ATMOSPHERE.bottom_radius), 0.0);
}

// Zenith angle of the horizon seen from radius r.
float HorizonZenithAngle(float r) {
  return PI - asin(clamp(AERIAL_ATMOSPHERE.bottom_radius / r, 0.0, 1.0));
}

// R_top^2 - r^2, without cancellation.
float SquaredTopBoundaryFromRadius(float r) {
  return (AERIAL_ATMOSPHERE.top_radius - r) * (AERIAL_ATMOSPHERE.top_radius + r);
}

// d = -r mu + sqrt(r^2 mu^2 + R_top^2 - r^2): the positive root of |x + d v| = R_top.
float DistanceToTopAtmosphereBoundary(float r, float mu) {
  float discriminant = r * r * mu * mu + SquaredTopBoundaryFromRadius(r);
  return ClampDistance(-r * mu + SafeSqrt(discriminant));
}

// Discriminant of |x + d v| = R_bottom: r^2 mu^2 - (r^2 - R_bottom^2).
float GroundDiscriminant(float r, float mu) {
  return r * r * mu * mu - SquaredHorizonDistance(r);
}

// d = -r mu - sqrt(discriminant): the nearer root of |x + d v| = R_bottom.
float DistanceToBottomAtmosphereBoundary(float r, float mu) {
  return ClampDistance(-r * mu - SafeSqrt(GroundDiscriminant(r, mu)));
}

// The ray hits the ground when it points down and the discriminant is non-negative.
bool RayIntersectsGround(float r, float mu) {
  return mu < 0.0 && GroundDiscriminant(r, mu) >= 0.0;
}

float DistanceToNearestAtmosphereBoundary(float r, float mu, bool ray_r_mu_intersects_ground) {
  return ray_r_mu_intersects_ground ? DistanceToBottomAtmosphereBoundary(r, mu)
                                    : DistanceToTopAtmosphereBoundary(r, mu);
}

// Radius and view cosine at distance d along the ray (law of cosines).
float RadiusAtDistance(float r, float mu, float d) {
  return ClampRadius(sqrt(d * d + 2.0 * r * mu * d + r * r));
}
float MuAtDistance(float r, float mu, float d, float r_d) {
  return ClampCosine((r * mu + d) / r_d);
}
// The sun is at infinity: cos(sun zenith) at the point is (r mu_s + d nu) / r_d.
float MuSAtDistance(float r, float mu_s, float nu, float d, float r_d) {
  return ClampCosine((r * mu_s + d * nu) / r_d);
}

float GetLayerDensity(DensityProfileLayer layer, float altitude) {
  float density = layer.exp_term * exp(layer.exp_scale * altitude) +
                  layer.linear_term * altitude + layer.constant_term;
  return clamp(density, 0.0, 1.0);
}

float GetProfileDensity(DensityProfile profile, float altitude) {
  return altitude < profile.layers[0].width ? GetLayerDensity(profile.layers[0], altitude)
                                            : GetLayerDensity(profile.layers[1], altitude);
}

#endif
