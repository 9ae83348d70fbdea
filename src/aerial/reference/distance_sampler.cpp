#include "aerial/reference/distance_sampler.h"

#include <algorithm>
#include <cmath>

namespace aerial::reference {
namespace {

// expm1(x) / x, continuous at 0: the integral over [0, 1] of exp(x t) dt.
double Expm1OverX(double x) { return std::abs(x) < 1e-9 ? 1.0 + 0.5 * x : std::expm1(x) / x; }

}  // namespace

void DistanceSampler::Build(const Medium& medium, const RayColumns& columns) {
  const AtmosphereParameters& a = medium.atmosphere();
  columns_ = &columns;
  const std::vector<double>& cuts = columns.cuts();
  const size_t n = cuts.size();
  for (Proxy& p : proxies_) p.g.resize(n);
  for (size_t i = 0; i < n; ++i) {
    Densities d = medium.At(RadiusAt(columns.r(), columns.mu(), cuts[i]) - medium.bottom_radius());
    Spectrum tau = medium.OpticalDepth(columns.cumulative()[i]);
    for (int c = 0; c < 3; ++c) {
      double sigma_s = a.rayleigh_scattering[c] * d.rayleigh + a.mie_scattering[c] * d.mie;
      proxies_[c].g[i] = sigma_s * std::exp(-tau[c]);
    }
  }
  active_count_ = 0;
  for (int c = 0; c < 3; ++c) {
    Proxy& p = proxies_[c];
    double g_max = *std::max_element(p.g.begin(), p.g.end());
    p.log_ratio.resize(n - 1);
    p.cdf.assign(1, 0.0);
    if (!(g_max > 0.0)) continue;
    for (double& g : p.g) g = std::max(g, 1e-3 * g_max);
    for (size_t i = 0; i + 1 < n; ++i) {
      p.log_ratio[i] = std::log(p.g[i + 1] / p.g[i]);
      // Integral of g_i exp(log_ratio t / L) over t in [0, L].
      p.cdf.push_back(p.cdf.back() + p.g[i] * (cuts[i + 1] - cuts[i]) * Expm1OverX(p.log_ratio[i]));
    }
    if (p.cdf.back() > 0.0) active_[active_count_++] = c;
  }
}

double DistanceSampler::PieceDensity(const Proxy& proxy, size_t piece, double t) const {
  double length = columns_->cuts()[piece + 1] - columns_->cuts()[piece];
  return proxy.g[piece] * std::exp(proxy.log_ratio[piece] * (length > 0.0 ? t / length : 0.0));
}

double DistanceSampler::Pdf(double s) const {
  const double length = columns_->length();
  if (length <= 0.0) return 0.0;
  if (active_count_ == 0) return 1.0 / length;
  size_t i = columns_->PieceIndex(s);
  double t = s - columns_->cuts()[i], proxy_pdf = 0.0;
  for (int k = 0; k < active_count_; ++k) {
    const Proxy& p = proxies_[active_[k]];
    proxy_pdf += PieceDensity(p, i, t) / p.cdf.back();
  }
  return kUniformFraction / length + (1.0 - kUniformFraction) * proxy_pdf / active_count_;
}

double DistanceSampler::SampleProxy(const Proxy& proxy, double u) const {
  // Invert the piecewise log-linear CDF: find the piece i, then solve
  // int_0^(t L) g_i exp(k y / L) dy = g_i L expm1(k t) / k = target - cdf_i for t in [0, 1]:
  // t = log1p(x k) / k with x = (target - cdf_i) / (g_i L).
  double target = u * proxy.cdf.back();
  size_t i = std::upper_bound(proxy.cdf.begin(), proxy.cdf.end(), target) - proxy.cdf.begin();
  i = std::clamp<size_t>(i, 1, proxy.cdf.size() - 1) - 1;
  double a = columns_->cuts()[i], piece_length = columns_->cuts()[i + 1] - a;
  double k = proxy.log_ratio[i], x = (target - proxy.cdf[i]) / (proxy.g[i] * piece_length);
  double t = std::abs(k) < 1e-9 ? x : std::log1p(x * k) / k;
  return a + piece_length * std::clamp(t, 0.0, 1.0);
}

double DistanceSampler::Sample(double u, double* pdf) const {
  const double length = columns_->length();
  double s;
  if (active_count_ == 0) {
    s = length * u;
  } else if (u < kUniformFraction) {
    s = length * u / kUniformFraction;
  } else {
    // One proxy chosen uniformly, the remaining fraction of u reused to sample it.
    double v = (u - kUniformFraction) / (1.0 - kUniformFraction) * active_count_;
    int k = std::min(static_cast<int>(v), active_count_ - 1);
    s = SampleProxy(proxies_[active_[k]], v - k);
  }
  *pdf = Pdf(s);
  return s;
}

}  // namespace aerial::reference
