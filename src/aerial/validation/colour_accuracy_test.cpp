#include "aerial/validation/colour_accuracy.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "aerial/error.h"

namespace aerial::validation {
namespace {

// Thrown from after_each_sample to cut a run short, as a killed process would.
struct CutShort {};

// Single scattering only: a quadrature, so a sample takes milliseconds and needs no more paths.
ColourReference SingleScatteringReference() { return {.orders = 1, .paths_per_query = 512}; }

// The reference's samples, up to `count` of them, in one run.
ColourReference RunUntil(const AtmosphereParameters& atmosphere, ColourReference reference, size_t count) {
  try {
    ContinueColourReference(atmosphere, reference, {}, [&](const ColourReference& so_far) {
      if (so_far.samples.size() == count) throw CutShort{};
    });
  } catch (const CutShort&) {
  }
  return reference;
}

void ExpectSameSample(const ColourSample& a, const ColourSample& b) {
  EXPECT_EQ(a.band, b.band);
  EXPECT_EQ(a.view.sun_zenith_deg, b.view.sun_zenith_deg);
  EXPECT_EQ(a.view.view_zenith_deg, b.view.view_zenith_deg);
  EXPECT_EQ(a.paths, b.paths);
  for (int q = 0; q < kColourQuantities; ++q)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(a.value[q][c], b.value[q][c]) << ToString(ColourQuantity(q)) << " " << c;
}

TEST(ColourReferenceFile, ARunCutShortContinuesFromItsFileAsIfItHadNotStopped) {
  const AtmosphereParameters earth = AtmosphereParameters::Earth();
  const std::filesystem::path file = std::filesystem::path(testing::TempDir()) / "cut_short_colour_reference.json";
  WriteColourReference(RunUntil(earth, SingleScatteringReference(), 2), file);

  ColourReference resumed = ReadColourReference(file);
  ASSERT_EQ(resumed.samples.size(), 2u);
  EXPECT_FALSE(IsComplete(resumed));
  resumed = RunUntil(earth, resumed, 4);

  const ColourReference whole = RunUntil(earth, SingleScatteringReference(), 4);
  ASSERT_EQ(resumed.samples.size(), 4u);
  ASSERT_EQ(whole.samples.size(), 4u);
  for (size_t i = 0; i < 4; ++i) ExpectSameSample(resumed.samples[i], whole.samples[i]);
  // The floors come from the first sample, which the continued run read from the file.
  for (int q = 0; q < kColourQuantities; ++q) {
    EXPECT_GT(whole.floors[q], 0.0);
    EXPECT_EQ(resumed.floors[q], whole.floors[q]);
  }
  std::filesystem::remove(file);
}

TEST(ColourReferenceFile, SamplesOfOtherViewsAreRefusedNotContinued) {
  const AtmosphereParameters earth = AtmosphereParameters::Earth();
  ColourReference reference = RunUntil(earth, SingleScatteringReference(), 1);
  ASSERT_EQ(reference.samples.size(), 1u);
  reference.samples[0].view.sun_zenith_deg = 45.0;  // no band holds 45 degrees
  try {
    ContinueColourReference(earth, reference);
    FAIL() << "a sample of another view was continued";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "colour reference sample");
    EXPECT_EQ(e.value(), "0");
  }
  EXPECT_EQ(reference.samples.size(), 1u);
}

}  // namespace
}  // namespace aerial::validation
