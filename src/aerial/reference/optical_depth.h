#pragma once
// Optical depth along rays by direct quadrature, tau = integral of beta_e(h(s)) ds with
// beta_e = beta_R rho_R + beta_M,ext rho_M + beta_O rho_O, and transmittance T = exp(-tau) (what
// Bruneton 2017's ComputeTransmittanceToTopAtmosphereBoundary approximates with 500 steps). The
// ray is cut where it crosses a level of Medium::level_radii or reaches its lowest point; on each
// piece every density is smooth and a fixed Gauss-Legendre rule (8 points for kReference, 4 for
// kMonteCarlo) integrates the three column densities at once.
#include <vector>

#include "aerial/reference/geometry.h"
#include "aerial/reference/medium.h"

namespace aerial::reference {

// Calls piece(s0, s1) for the consecutive pieces of [0, length] of the ray from radius r with
// zenith cosine mu. A level radius rho is crossed at s = -r mu -+ sqrt(r^2 (mu^2 - 1) + rho^2)
// (going down, then up); the lowest point is s = -r mu.
template <typename Piece>
void ForEachPiece(const std::vector<double>& radii, double r, double mu, double length, Piece&& piece) {
  double s_prev = 0.0;
  auto cut = [&](double s) {
    if (s > s_prev && s < length) {
      piece(s_prev, s);
      s_prev = s;
    }
  };
  double r_lowest = r;
  if (mu < 0.0) {
    r_lowest = r * std::sqrt(1.0 - mu * mu);
    auto it = std::lower_bound(radii.begin(), radii.end(), r);
    while (it != radii.begin()) {
      double discriminant = Discriminant(r, mu, *--it);
      if (discriminant < 0.0) break;
      cut(-r * mu - std::sqrt(discriminant));
    }
    cut(-r * mu);
  }
  for (auto it = std::upper_bound(radii.begin(), radii.end(), r_lowest); it != radii.end(); ++it)
    cut(-r * mu + SafeSqrt(Discriminant(r, mu, *it)));
  if (length > s_prev) piece(s_prev, length);
}

// Column densities over [s0, s1] of the ray, one piece (smooth densities).
Column ComputePieceColumn(const Medium& medium, Accuracy accuracy, double r, double mu, double s0,
                          double s1);

// Column densities over the first `length` meters of the ray.
Column ComputeColumn(const Medium& medium, Accuracy accuracy, double r, double mu, double length);

// Transmittance over the first `length` meters of the ray.
Spectrum ComputeTransmittance(const Medium& medium, Accuracy accuracy, double r, double mu,
                              double length);

// The pieces of one ray with the column densities accumulated up to each cut, so that the column
// up to any s costs one piece's quadrature. Reusable (Build keeps its storage).
class RayColumns {
 public:
  void Build(const Medium& medium, Accuracy accuracy, double r, double mu, double length);

  double r() const { return r_; }
  double mu() const { return mu_; }
  double length() const { return cuts_.back(); }
  // Cuts s_0 = 0 < s_1 < ... < s_m = length, and the columns over [0, s_i].
  const std::vector<double>& cuts() const { return cuts_; }
  const std::vector<Column>& cumulative() const { return cumulative_; }
  // Index i of the piece [s_i, s_i+1] holding s (clamped to [0, length]).
  size_t PieceIndex(double s) const;
  Column ColumnTo(double s) const;

 private:
  const Medium* medium_ = nullptr;
  Accuracy accuracy_ = Accuracy::kReference;
  double r_ = 0.0, mu_ = 0.0;
  std::vector<double> cuts_;
  std::vector<Column> cumulative_;
};

}  // namespace aerial::reference
