#pragma once
// Quadrature rules: fixed Gauss-Legendre for smooth pieces of rays, and a globally adaptive
// Gauss-Kronrod (7, 15) integrator for vector-valued integrands with kinks (QUADPACK's QAG
// strategy: always bisect the interval with the largest error estimate).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace aerial::reference {

// Gauss-Legendre nodes in (0, 1) and weights on [-1, 1] (Abramowitz & Stegun, table 25.4);
// the nodes are +-x.
inline constexpr std::array<double, 2> kGaussLegendre4X = {0.3399810435848563, 0.8611363115940526};
inline constexpr std::array<double, 2> kGaussLegendre4W = {0.6521451548625461, 0.3478548451374538};
inline constexpr std::array<double, 4> kGaussLegendre8X = {0.1834346424956498, 0.5255324099163290,
                                                           0.7966664774136267, 0.9602898564975363};
inline constexpr std::array<double, 4> kGaussLegendre8W = {0.3626837833783620, 0.3137066458778873,
                                                           0.2223810344533745, 0.1012285362903763};

// Calls visit(s, weight) for the n-point rule on [a, b], n = 2 * X.size().
template <size_t M, typename Visit>
void ForEachGaussLegendreNode(const std::array<double, M>& x, const std::array<double, M>& w,
                              double a, double b, Visit&& visit) {
  double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (size_t i = 0; i < M; ++i) {
    visit(mid - half * x[i], half * w[i]);
    visit(mid + half * x[i], half * w[i]);
  }
}

template <size_t N>
using Values = std::array<double, N>;

// Integrates f: double -> Values<N> over [breakpoints.front(), breakpoints.back()], the
// breakpoints being known kinks. Stops when, for every component c, the summed |K15 - G7|
// estimates are below rel_tol * |integral_c| (or below 1e-300 for an identically zero c), or
// after max_intervals intervals.
template <size_t N, typename F>
Values<N> IntegrateAdaptive(F&& f, const std::vector<double>& breakpoints, double rel_tol,
                            int max_intervals = 4000) {
  // QUADPACK qk15: Kronrod nodes (the odd ones are the Gauss nodes) and weights.
  static constexpr double xk[8] = {0.991455371120812639, 0.949107912342758525, 0.864864423359769073,
                                   0.741531185599394440, 0.586087235467691130, 0.405845151377397167,
                                   0.207784955007898468, 0.0};
  static constexpr double wk[8] = {0.022935322010529225, 0.063092092629978553, 0.104790010322250184,
                                   0.140653259715525919, 0.169004726639267903, 0.190350578064785410,
                                   0.204432940075298892, 0.209482141084727828};
  static constexpr double wg[4] = {0.129484966168869693, 0.279705391489276668, 0.381830050505118945,
                                   0.417959183673469388};
  struct Interval {
    double a, b;
    Values<N> value, error;
  };
  auto rule = [&](double a, double b) {
    Interval in{a, b, {}, {}};
    double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    Values<N> gauss{};
    for (int i = 0; i < 8; ++i) {
      for (double sign : {-1.0, 1.0}) {
        if (i == 7 && sign > 0.0) break;  // the centre once.
        Values<N> v = f(mid + sign * half * xk[i]);
        for (size_t c = 0; c < N; ++c) {
          in.value[c] += half * wk[i] * v[c];
          if (i % 2 == 1) gauss[c] += half * wg[i / 2] * v[c];
        }
      }
    }
    for (size_t c = 0; c < N; ++c) in.error[c] = std::abs(in.value[c] - gauss[c]);
    return in;
  };
  std::vector<Interval> intervals;
  for (size_t i = 0; i + 1 < breakpoints.size(); ++i) {
    if (breakpoints[i + 1] > breakpoints[i]) intervals.push_back(rule(breakpoints[i], breakpoints[i + 1]));
  }
  Values<N> total{};
  while (true) {
    Values<N> error{};
    total = {};
    for (const Interval& in : intervals) {
      for (size_t c = 0; c < N; ++c) total[c] += in.value[c], error[c] += in.error[c];
    }
    auto badness = [&](const Interval& in) {
      double worst = 0.0;
      for (size_t c = 0; c < N; ++c)
        worst = std::max(worst, in.error[c] / std::max(rel_tol * std::abs(total[c]), 1e-300));
      return worst;
    };
    bool converged = true;
    for (size_t c = 0; c < N; ++c)
      converged = converged && error[c] <= std::max(rel_tol * std::abs(total[c]), 1e-300);
    if (converged || intervals.empty() || static_cast<int>(intervals.size()) >= max_intervals) break;
    auto worst = std::max_element(intervals.begin(), intervals.end(),
                                  [&](const Interval& x, const Interval& y) { return badness(x) < badness(y); });
    double a = worst->a, b = worst->b, m = 0.5 * (a + b);
    *worst = rule(a, m);
    intervals.push_back(rule(m, b));
  }
  return total;
}

}  // namespace aerial::reference
