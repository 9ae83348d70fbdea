#pragma once
// Importance sampling of a scattering point along a ray segment. For each wavelength c the ideal
// density is proportional to beta_s,c(s) T_c(0, s); its proxy g_c is known exactly at the cuts
// of a RayColumns and interpolated log-linearly in between, where every density is smooth and
// close to exponential in s. The three proxies are combined by one-sample spectral MIS (balance
// heuristic: pdf = their average, Wilkie et al. 2014, "Hero Wavelength Spectral Sampling"), so no
// channel's weight exceeds 3x what its own proxy would give. Each g_c is floored at 1e-3 of its
// maximum and 5% of a uniform density is mixed in ("defensive" sampling, Hesterberg 1995): the
// pdf is positive wherever the integrand may be, keeping the estimator unbiased.
#include <array>
#include <vector>

#include "aerial/reference/medium.h"
#include "aerial/reference/optical_depth.h"

namespace aerial::reference {

class DistanceSampler {
 public:
  // Reusable: Build keeps its storage. `columns` must outlive the sampler's use.
  void Build(const Medium& medium, const RayColumns& columns);

  // Maps u in [0, 1) to a distance s in [0, length] and sets *pdf to its density (per meter).
  double Sample(double u, double* pdf) const;
  double Pdf(double s) const;

 private:
  struct Proxy {
    std::vector<double> g;          // at the cuts.
    std::vector<double> log_ratio;  // ln(g_i+1 / g_i) per piece.
    std::vector<double> cdf;        // integral of the interpolated proxy up to each cut.
  };
  double PieceDensity(const Proxy& proxy, size_t piece, double t) const;  // at s_piece + t.
  double SampleProxy(const Proxy& proxy, double u) const;

  static constexpr double kUniformFraction = 0.05;
  const RayColumns* columns_ = nullptr;
  std::array<Proxy, 3> proxies_;
  int active_[3] = {0, 0, 0};  // indices of the proxies with a positive integral.
  int active_count_ = 0;
};

}  // namespace aerial::reference
