#include "aerial/reference/optical_depth.h"

#include "aerial/reference/quadrature.h"

namespace aerial::reference {

Column ComputePieceColumn(const Medium& medium, Accuracy accuracy, double r, double mu, double s0,
                          double s1) {
  Column column;
  const double bottom = medium.bottom_radius();
  auto visit = [&](double s, double weight) {
    Densities d = medium.At(RadiusAt(r, mu, s) - bottom);
    column.rayleigh += weight * d.rayleigh;
    column.mie += weight * d.mie;
    column.absorption += weight * d.absorption;
  };
  if (accuracy == Accuracy::kReference) {
    ForEachGaussLegendreNode(kGaussLegendre8X, kGaussLegendre8W, s0, s1, visit);
  } else {
    ForEachGaussLegendreNode(kGaussLegendre4X, kGaussLegendre4W, s0, s1, visit);
  }
  return column;
}

Column ComputeColumn(const Medium& medium, Accuracy accuracy, double r, double mu, double length) {
  Column column;
  ForEachPiece(medium.level_radii(accuracy), r, mu, length, [&](double s0, double s1) {
    column = column + ComputePieceColumn(medium, accuracy, r, mu, s0, s1);
  });
  return column;
}

Spectrum ComputeTransmittance(const Medium& medium, Accuracy accuracy, double r, double mu,
                              double length) {
  return medium.Transmittance(ComputeColumn(medium, accuracy, r, mu, length));
}

void RayColumns::Build(const Medium& medium, Accuracy accuracy, double r, double mu, double length) {
  medium_ = &medium;
  accuracy_ = accuracy;
  r_ = r;
  mu_ = mu;
  cuts_.assign(1, 0.0);
  cumulative_.assign(1, Column{});
  ForEachPiece(medium.level_radii(accuracy), r, mu, length, [&](double s0, double s1) {
    cumulative_.push_back(cumulative_.back() + ComputePieceColumn(medium, accuracy, r, mu, s0, s1));
    cuts_.push_back(s1);
  });
}

size_t RayColumns::PieceIndex(double s) const {
  size_t i = std::upper_bound(cuts_.begin(), cuts_.end(), s) - cuts_.begin();
  return std::clamp<size_t>(i, 1, std::max<size_t>(cuts_.size() - 1, 1)) - 1;
}

Column RayColumns::ColumnTo(double s) const {
  s = std::clamp(s, 0.0, length());
  size_t i = PieceIndex(s);
  if (s <= cuts_[i]) return cumulative_[i];
  return cumulative_[i] + ComputePieceColumn(*medium_, accuracy_, r_, mu_, cuts_[i], s);
}

}  // namespace aerial::reference
