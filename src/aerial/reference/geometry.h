#pragma once
// Ray-sphere geometry of a spherical planet centred at the origin, in the (r, mu, mu_s, nu)
// parameterization of Bruneton 2017 (functions.glsl, "Intersections" and "Single scattering").
// A point at distance d along a ray from radius r with zenith cosine mu has (law of cosines)
//   r_d = sqrt(d^2 + 2 r mu d + r^2),  mu_d = (r mu + d) / r_d,  mu_s_d = (r mu_s + d nu) / r_d.
#include <algorithm>
#include <cmath>
#include <numbers>

namespace aerial::reference {

// Rounding can push a cosine or a discriminant slightly out of its domain (Bruneton's ClampCosine,
// SafeSqrt).
inline double ClampCosine(double mu) { return std::clamp(mu, -1.0, 1.0); }
inline double SafeSqrt(double a) { return std::sqrt(std::max(a, 0.0)); }

// r^2 (mu^2 - 1) + radius^2, written as (radius - r)(radius + r) + (r mu)^2 to avoid the
// cancellation of two ~4e13 m^2 terms near the tangent.
inline double Discriminant(double r, double mu, double radius) {
  return (radius - r) * (radius + r) + (r * mu) * (r * mu);
}

// Far intersection with a sphere of radius >= r: -r mu + sqrt(r^2 (mu^2 - 1) + radius^2).
inline double DistanceToOuterSphere(double r, double mu, double radius) {
  return std::max(-r * mu + SafeSqrt(Discriminant(r, mu, radius)), 0.0);
}

// Near intersection with a sphere of radius <= r: -r mu - sqrt(r^2 (mu^2 - 1) + radius^2),
// meaningful only when RayIntersectsInnerSphere.
inline double DistanceToInnerSphere(double r, double mu, double radius) {
  return std::max(-r * mu - SafeSqrt(Discriminant(r, mu, radius)), 0.0);
}

// The ray goes down and its line passes within `radius` of the centre, i.e.
// mu < -sqrt(1 - (radius / r)^2) (Bruneton's RayIntersectsGround).
inline bool RayIntersectsInnerSphere(double r, double mu, double radius) {
  return mu < 0.0 && Discriminant(r, mu, radius) >= 0.0;
}

// Radius of the point at distance d along the ray (law of cosines).
inline double RadiusAt(double r, double mu, double d) {
  return std::sqrt(std::max(d * d + 2.0 * r * mu * d + r * r, 0.0));
}

// Cosine of the horizon's zenith angle seen from radius r >= bottom_radius: -sqrt(1 - (R/r)^2).
inline double CosHorizon(double r, double bottom_radius) {
  double sin_theta_h = std::min(bottom_radius / r, 1.0);
  return -SafeSqrt(1.0 - sin_theta_h * sin_theta_h);
}

}  // namespace aerial::reference
