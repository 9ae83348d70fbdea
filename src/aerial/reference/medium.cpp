#include "aerial/reference/medium.h"

namespace aerial::reference {
namespace {

double Mean(const Spectrum& s) { return (s[0] + s[1] + s[2]) / 3.0; }

double Unclamped(const DensityProfileLayer& l, double h) {
  return l.exp_term * std::exp(l.exp_scale_per_m * h) + l.linear_term_per_m * h + l.constant_term;
}

// Altitudes in (lo, hi) where the unclamped layer density crosses `target` (a clamp kink): sign
// changes on a 4096-step scan, refined by bisection. A tangency without crossing is no kink.
void AddCrossings(const DensityProfileLayer& l, double lo, double hi, double target,
                  std::vector<double>* levels) {
  const int steps = 4096;
  for (int i = 0; i < steps; ++i) {
    double a = lo + (hi - lo) * i / steps, b = lo + (hi - lo) * (i + 1) / steps;
    bool below_a = Unclamped(l, a) < target;
    if (below_a == (Unclamped(l, b) < target)) continue;
    for (int k = 0; k < 100 && b - a > 1e-9; ++k) {
      double m = 0.5 * (a + b);
      ((Unclamped(l, m) < target) == below_a ? a : b) = m;
    }
    levels->push_back(0.5 * (a + b));
  }
}

void AddProfileLevels(const DensityProfile& profile, double top, double spacing_scale_heights,
                      double negligible_above, std::vector<double>* levels) {
  const double width = profile.layers[0].width_m;
  if (width > 0.0 && width < top) levels->push_back(width);
  struct Range {
    const DensityProfileLayer& layer;
    double lo, hi;
  };
  for (const Range& range : {Range{profile.layers[0], 0.0, std::min(width, top)},
                             Range{profile.layers[1], std::max(width, 0.0), top}}) {
    if (range.hi <= range.lo) continue;
    const DensityProfileLayer& l = range.layer;
    AddCrossings(l, range.lo, range.hi, 0.0, levels);
    AddCrossings(l, range.lo, range.hi, 1.0, levels);
    if (l.exp_term == 0.0 || l.exp_scale_per_m == 0.0) continue;
    double step = spacing_scale_heights / std::abs(l.exp_scale_per_m);
    for (double h = range.lo + step; h < range.hi; h += step) {
      levels->push_back(h);
      if (h >= negligible_above) break;
    }
  }
}

// The altitude above which the species' extinction stays under kNegligibleShare of the whole
// medium's at every wavelength: there an error of its column, even of 100%, moves no optical
// depth by more than that share. Scanned every 10 m from the top down.
constexpr double kNegligibleShare = 1e-6;

double NegligibleAbove(const AtmosphereParameters& a, const DensityProfile& profile,
                       const Spectrum& extinction) {
  const double top = a.top_radius_m - a.bottom_radius_m;
  for (double h = top; h > 0.0; h -= 10.0) {
    double own = ProfileDensity(profile, h), rayleigh = ProfileDensity(a.rayleigh_density, h),
           mie = ProfileDensity(a.mie_density, h), absorption = ProfileDensity(a.absorption_density, h);
    for (int c = 0; c < 3; ++c) {
      double total = a.rayleigh_scattering[c] * rayleigh + a.mie_extinction[c] * mie +
                     a.absorption_extinction[c] * absorption;
      if (!(extinction[c] * own < kNegligibleShare * total)) return h;
    }
  }
  return 0.0;
}

// negligible: whether a species' exponential term stops being refined where it is negligible
// (NegligibleAbove), or is refined up to the top.
std::vector<double> LevelRadii(const AtmosphereParameters& a, double spacing_scale_heights, bool negligible) {
  double top = a.top_radius_m - a.bottom_radius_m;
  std::vector<double> levels = {0.0, top};
  struct Species {
    const DensityProfile& profile;
    const Spectrum& extinction;
  };
  for (const Species& s : {Species{a.rayleigh_density, a.rayleigh_scattering}, Species{a.mie_density, a.mie_extinction},
                           Species{a.absorption_density, a.absorption_extinction}}) {
    double negligible_above = negligible ? NegligibleAbove(a, s.profile, s.extinction) : top;
    AddProfileLevels(s.profile, top, spacing_scale_heights, negligible_above, &levels);
  }
  std::sort(levels.begin(), levels.end());
  std::vector<double> radii;
  for (double h : levels) {
    // Levels closer than 1 mm would only create empty pieces.
    if (h < 0.0 || h > top || (!radii.empty() && a.bottom_radius_m + h - radii.back() < 1e-3))
      continue;
    radii.push_back(a.bottom_radius_m + h);
  }
  radii.back() = a.top_radius_m;
  return radii;
}

}  // namespace

Medium::Medium(const AtmosphereParameters& atmosphere)
    : atmosphere_(atmosphere),
      mean_rayleigh_(Mean(atmosphere.rayleigh_scattering)),
      mean_mie_extinction_(Mean(atmosphere.mie_extinction)),
      mean_absorption_(Mean(atmosphere.absorption_extinction)),
      reference_levels_(LevelRadii(atmosphere, 2.0, false)),
      monte_carlo_levels_(LevelRadii(atmosphere, 4.0, true)) {}

Spectrum Medium::OpticalDepth(const Column& c) const {
  Spectrum tau;
  for (int i = 0; i < 3; ++i) {
    tau[i] = atmosphere_.rayleigh_scattering[i] * c.rayleigh +
             atmosphere_.mie_extinction[i] * c.mie + atmosphere_.absorption_extinction[i] * c.absorption;
  }
  return tau;
}

Spectrum Medium::Transmittance(const Column& c) const {
  Spectrum t = OpticalDepth(c);
  for (double& v : t) v = std::exp(-v);
  return t;
}

}  // namespace aerial::reference
