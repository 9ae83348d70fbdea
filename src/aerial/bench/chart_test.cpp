#include "aerial/bench/chart.h"

#include <gtest/gtest.h>

#include <cmath>

#include "aerial/bench/picture_test_util.h"
#include "aerial/error.h"

namespace aerial::bench {
namespace {

constexpr Rgb kGreen{0, 150, 0};
constexpr int kWidth = 600, kHeight = 400;

// Three points on the diagonal, given out of order: both axes run from 1 to 100. No title or
// axis labels, so that only the plot, its numbers and the legend are drawn.
ChartSpec Diagonal(bool square_markers = false) {
  return {.series = {{"s", kGreen, square_markers, {{100.0, 100.0}, {1.0, 1.0}, {10.0, 10.0}}}}};
}

// The plot's frame, found from its axes: the y axis is the column with the most ink, the x axis
// the row with the most; the last tick below the x axis marks its right end, the last tick left
// of the y axis its top.
struct Plot {
  int left = 0, right = 0, top = 0, bottom = 0;
  // Where a value falls, log10 of it as a fraction of the axis (1 to 100: 2 decades).
  int X(double v) const { return int(std::floor(left + 0.5 + std::log10(v) / 2.0 * (right - left))); }
  int Y(double v) const { return int(std::floor(bottom + 0.5 - std::log10(v) / 2.0 * (bottom - top))); }
};

Plot FindPlot(const Picture& p) {
  Plot plot;
  auto ink_in = [&](Box box) { return Count(p, box, kInk); };
  for (int x = 0; x < p.width; ++x)
    if (ink_in({x, 0, x + 1, p.height}) > ink_in({plot.left, 0, plot.left + 1, p.height})) plot.left = x;
  for (int y = 0; y < p.height; ++y)
    if (ink_in({0, y, p.width, y + 1}) > ink_in({0, plot.bottom, p.width, plot.bottom + 1})) plot.bottom = y;
  plot.right = BoxOf(p, kInk, {0, plot.bottom + 2, p.width, plot.bottom + 3}).x1 - 1;
  plot.top = BoxOf(p, kInk, {plot.left - 2, 0, plot.left - 1, p.height}).y0;
  return plot;
}

TEST(LogLogChart, PointsAndLinesSitOnTheLogAxes) {
  Picture chart = LogLogChart(Diagonal(), kWidth, kHeight);
  ASSERT_EQ(chart.width, kWidth);
  ASSERT_EQ(chart.height, kHeight);
  Plot plot = FindPlot(chart);
  SCOPED_TRACE(testing::Message() << "plot x " << plot.left << "-" << plot.right << ", y " << plot.top << "-"
                                  << plot.bottom);
  ASSERT_GT(plot.right - plot.left, kWidth / 2);
  ASSERT_GT(plot.bottom - plot.top, kHeight / 2);
  for (double v : {1.0, 10.0, 100.0}) EXPECT_EQ(chart.At(plot.X(v), plot.Y(v)), kGreen) << "marker at " << v;
  EXPECT_EQ(chart.At(plot.X(std::sqrt(10.0)), plot.Y(std::sqrt(10.0))), kGreen) << "the line from 1 to 10";
  EXPECT_EQ(chart.At(plot.X(30.0), plot.Y(3.0)), kPaper) << "off the line, between grid lines";
}

// A square's corner is 4 pixels across and down from its centre; a disc of radius 5 does not
// reach it (the line leaves the marker up and to the right).
TEST(LogLogChart, MarkersAreRoundOrSquare) {
  for (bool square : {false, true}) {
    Picture chart = LogLogChart(Diagonal(square), kWidth, kHeight);
    Plot plot = FindPlot(chart);
    EXPECT_EQ(chart.At(plot.X(10.0) + 4, plot.Y(10.0) + 4) == kGreen, square) << (square ? "square" : "round");
  }
}

// Each label drawn changes only its own place: the title and then the y axis' label above the
// plot, the x axis' label below the axis' numbers and centred under the plot, the series' label
// in the legend at the plot's top left.
TEST(LogLogChart, LabelsAreDrawnInTheirPlaces) {
  Picture bare = LogLogChart(Diagonal(), kWidth, kHeight);
  Plot plot = FindPlot(bare);
  auto changed_by = [&](auto edit) {
    ChartSpec spec = Diagonal();
    edit(spec);
    return Changed(LogLogChart(spec, kWidth, kHeight), bare);
  };
  Box title = changed_by([](ChartSpec& s) { s.title = "Precompute time"; });
  Box y_label = changed_by([](ChartSpec& s) { s.y_label = "GPU ms"; });
  Box x_label = changed_by([](ChartSpec& s) { s.x_label = "Table memory"; });
  Box legend = changed_by([](ChartSpec& s) { s.series[0].label = "4D tables"; });
  Box above{0, 0, kWidth / 2, plot.top};
  EXPECT_TRUE(title.Inside(above)) << title;
  EXPECT_TRUE(y_label.Inside(above)) << y_label;
  EXPECT_LE(title.y1, y_label.y0) << title << " over " << y_label;
  EXPECT_TRUE(x_label.Inside({0, plot.bottom + 20, kWidth, kHeight})) << x_label;
  EXPECT_NEAR((x_label.x0 + x_label.x1) / 2.0, (plot.left + plot.right) / 2.0, 2.0) << x_label;
  EXPECT_TRUE(legend.Inside({plot.left + 1, plot.top + 1, plot.left + kWidth / 3, plot.top + 60})) << legend;
  for (const Box& label : {title, y_label, x_label, legend}) EXPECT_GT(label.Width(), 20) << label;
}

// Each series' line and marker in a row of its own in the legend, at the plot's top left, away
// from both series' points.
TEST(LogLogChart, LegendShowsEachSeriesInItsOwnRow) {
  constexpr Rgb kBlue{0, 0, 200};
  ChartSpec spec = Diagonal();
  spec.series.push_back({"t", kBlue, true, {{1.0, 2.0}, {100.0, 50.0}}});
  Picture chart = LogLogChart(spec, kWidth, kHeight);
  Plot plot = FindPlot(chart);
  Box legend{plot.left + 1, plot.top + 1, plot.left + kWidth / 3, plot.top + 80};
  Box first = BoxOf(chart, kGreen, legend), second = BoxOf(chart, kBlue, legend);
  for (const Box& row : {first, second}) {
    EXPECT_GE(row.Width(), 20) << row << ": a line through a marker";
    EXPECT_LE(row.Height(), 11) << row << ": a marker tall";
  }
  EXPECT_LE(first.y1, second.y0) << first << " above " << second;
  EXPECT_NEAR(first.x0, second.x0, 1) << first << " beside " << second;
}

TEST(LogLogChart, RefusesPointsALogAxisCannotShow) {
  ChartSpec spec = Diagonal();
  spec.series[0].points.push_back({0.0, 1.0});
  EXPECT_THROW(LogLogChart(spec, kWidth, kHeight), Error);
  spec.series[0].points = {};
  EXPECT_THROW(LogLogChart(spec, kWidth, kHeight), Error);
}

}  // namespace
}  // namespace aerial::bench
