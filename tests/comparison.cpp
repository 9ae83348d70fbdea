#include "comparison.h"

#include <cmath>
#include <cstdio>

namespace aerial::testing {

std::vector<ViewAngles> ViewGrid(const std::vector<double>& altitudes_m,
                                 const std::vector<double>& view_zeniths_deg,
                                 const std::vector<double>& sun_zeniths_deg,
                                 const std::vector<double>& azimuths_deg) {
  std::vector<ViewAngles> views;
  for (double h : altitudes_m)
    for (double v : view_zeniths_deg)
      for (double s : sun_zeniths_deg)
        for (double a : azimuths_deg) views.push_back({h, v, s, a});
  return views;
}

std::string Describe(const ViewAngles& view) {
  char text[160];
  std::snprintf(text, sizeof text, "altitude %.0f m, view zenith %.2f deg, sun zenith %.1f deg, azimuth %.0f deg",
                view.altitude_m, view.view_zenith_deg, view.sun_zenith_deg, view.azimuth_deg);
  return text;
}

void WorstError::Add(double actual, double expected, const std::string& where) {
  if (!(std::abs(expected) >= floor_)) return;
  ++samples_;
  double error = std::abs(actual - expected) / std::abs(expected);
  if (!(error <= worst_)) {  // also catches NaN
    worst_ = std::isnan(error) ? INFINITY : error;
    where_ = where;
  }
}

void WorstError::Add(const Spectrum& actual, const Spectrum& expected, const std::string& where) {
  static const char* kChannel[] = {" (red)", " (green)", " (blue)"};
  for (int i = 0; i < 3; ++i) Add(actual[i], expected[i], where + kChannel[i]);
}

std::string WorstError::Summary() const {
  char text[64];
  std::snprintf(text, sizeof text, "worst %.4f%% over %d samples at ", 100.0 * worst_, samples_);
  return text + where_;
}

::testing::AssertionResult ComparedExactly(const WorstError& worst, int samples) {
  if (worst.samples() == samples) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "compared " << worst.samples() << " samples, expected exactly "
                                       << samples << " (" << worst.Summary() << ")";
}

::testing::AssertionResult ComparedAtLeast(const WorstError& worst, int samples) {
  if (worst.samples() >= samples) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "compared " << worst.samples() << " samples, expected at least "
                                       << samples << " (" << worst.Summary() << ")";
}

}  // namespace aerial::testing
