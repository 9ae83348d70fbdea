#pragma once
// A minimal double-precision 3-vector for the path tracer, whose paths leave the plane of the
// camera, the view direction and the sun. World frame: planet centre at the origin.
#include <algorithm>
#include <cmath>

namespace aerial::reference {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double Dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double Length(Vec3 a) { return std::sqrt(Dot(a, a)); }
inline Vec3 Normalize(Vec3 a) { return (1.0 / Length(a)) * a; }

// Direction at polar cosine cos_theta and azimuth phi around the unit axis n, using the
// branchless orthonormal basis of Duff et al. 2017 ("Building an Orthonormal Basis, Revisited").
inline Vec3 AroundAxis(Vec3 n, double cos_theta, double phi) {
  double sign = std::copysign(1.0, n.z);
  double a = -1.0 / (sign + n.z);
  double b = n.x * n.y * a;
  Vec3 t{1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
  Vec3 u{b, sign + n.y * n.y * a, -n.y};
  double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return (sin_theta * std::cos(phi)) * t + (sin_theta * std::sin(phi)) * u + cos_theta * n;
}

}  // namespace aerial::reference
