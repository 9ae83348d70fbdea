#include "aerial/viewer/frame_accumulator.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>

namespace aerial::viewer {
namespace {

// The jitters are the centres of a pixel's four quadrants, each once: the sample points of a 2x2
// supersampled pixel, about the pixel's centre.
TEST(FrameAccumulation, JittersAreTheFourQuadrantCentres) {
  std::set<std::pair<double, double>> seen;
  for (int frame = 0; frame < 4; ++frame) {
    glm::dvec2 jitter = NextAccumulationStep(frame).jitter_px;
    EXPECT_DOUBLE_EQ(std::abs(jitter.x), 0.25) << frame;
    EXPECT_DOUBLE_EQ(std::abs(jitter.y), 0.25) << frame;
    seen.insert({jitter.x, jitter.y});
  }
  EXPECT_EQ(seen.size(), 4u);
  // The first two are opposite quadrants: after two frames both diagonals are sampled.
  EXPECT_EQ(NextAccumulationStep(0).jitter_px, -NextAccumulationStep(1).jitter_px);
}

// accumulate.comp's update, average += (frame - average) * weight, with these weights is the plain
// mean of the frames so far, at every step.
TEST(FrameAccumulation, WeightsMakeThePlainMean) {
  const double frames[4] = {3.0, -1.0, 10.0, 0.5};
  double average = 0.0, sum = 0.0;
  for (int n = 0; n < 4; ++n) {
    double weight = NextAccumulationStep(n).weight;
    average += (frames[n] - average) * weight;
    sum += frames[n];
    EXPECT_NEAR(average, sum / (n + 1), 1e-6) << n;  // float weights: 1e-7 relative
  }
  EXPECT_FLOAT_EQ(NextAccumulationStep(0).weight, 1.0f);  // the first frame replaces what was there
}

}  // namespace
}  // namespace aerial::viewer
