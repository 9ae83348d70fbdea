#pragma once
// Helpers of the tables-vs-reference tests: a grid of views and the worst relative error over it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "aerial/atmosphere.h"
#include "aerial/view_geometry.h"

namespace aerial::testing {

// Altitudes (ground, 10 km, 50 km), view zeniths near, at and below the horizon, sun zeniths from
// noon down to the lowest sun elevation (120 degrees), azimuths toward, across and away from the sun.
std::vector<ViewAngles> ViewGrid(const std::vector<double>& altitudes_m,
                                 const std::vector<double>& view_zeniths_deg,
                                 const std::vector<double>& sun_zeniths_deg,
                                 const std::vector<double>& azimuths_deg);

std::string Describe(const ViewAngles& view);

// Keeps the largest relative error |a - b| / |b| over the samples where |b| >= floor.
class WorstError {
 public:
  explicit WorstError(double floor) : floor_(floor) {}
  void Add(double actual, double expected, const std::string& where);
  void Add(const Spectrum& actual, const Spectrum& expected, const std::string& where);
  double value() const { return worst_; }
  const std::string& where() const { return where_; }
  int samples() const { return samples_; }
  std::string Summary() const;

 private:
  double floor_;
  double worst_ = 0.0;
  std::string where_;
  int samples_ = 0;
};

// A worst error over no samples is 0 and passes any bound, so every comparison also checks how
// many samples it compared (those at or above its floor): exactly, where the grid and the
// expected values fix the count, or at least a minimum the caller justifies.
::testing::AssertionResult ComparedExactly(const WorstError& worst, int samples);
::testing::AssertionResult ComparedAtLeast(const WorstError& worst, int samples);

}  // namespace aerial::testing
