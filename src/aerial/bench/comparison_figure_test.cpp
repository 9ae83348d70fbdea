#include "aerial/bench/comparison_figure.h"

#include <gtest/gtest.h>

#include <array>

#include "aerial/bench/heatmap.h"
#include "aerial/bench/picture_test_util.h"
#include "aerial/image/exposure.h"

namespace aerial::bench {
namespace {

constexpr int kW = 120, kH = 40;  // below kMaxPanelWidth: drawn at full size
// The 3D frame is 25% brighter in this block, the same as the 4D frame elsewhere. The frames are
// orange, a colour no grey of the labels' edges can take.
constexpr Box kBlock{30, 10, 50, 20};
constexpr std::array<float, 4> kOrange{1.0f, 0.5f, 0.25f, 1.0f};

ImageRgbF Filled(std::array<float, 4> rgba) {
  ImageRgbF image{kW, kH, {}};
  for (int i = 0; i < kW * kH; ++i) image.rgba.insert(image.rgba.end(), rgba.begin(), rgba.end());
  return image;
}

FigureImages BrighterBlock() {
  FigureImages images{"noon", Filled(kOrange), Filled(kOrange), Filled({0.0f, 0.0f, 0.0f, -1.0f})};  // all sky
  for (int y = kBlock.y0; y < kBlock.y1; ++y)
    for (int x = kBlock.x0; x < kBlock.x1; ++x)
      for (int c = 0; c < 3; ++c) images.lut3d.pixel(x, y)[c] *= 1.25f;
  return images;
}

Box Moved(const Box& b, int x, int y) { return {b.x0 + x, b.y0 + y, b.x1 + x, b.y1 + y}; }

// Where the panels are: the heat map by the colour of no difference, the two frames, side by side
// left of it, by the frames' colour tone-mapped with the 4D frame's metered exposure.
struct Panels {
  Box map, frames;
  Rgb frame, block;  // the frames' colour, the 3D frame's in the block
};

Panels FindPanels(const Picture& figure, const FigureImages& images) {
  ToneMapOptions tone{.exposure = Exposure{}.MultiplierFor(images.lut4d)};
  Picture lut3d{kW, kH, ToneMapToSrgb8(images.lut3d, tone)};
  Panels panels{.frame = lut3d.At(0, 0), .block = lut3d.At(kBlock.x0, kBlock.y0)};
  panels.map = BoxOf(figure, HeatColor(0.0));
  panels.frames = BoxOf(figure, panels.frame);
  return panels;
}

// The block is 200 of 4800 pixels, so the 99th percentile is its error, 0.25; the scale rounds
// up to 0.5, so the block shows HeatColor(0.5) and the rest HeatColor(0).
TEST(ComparisonFigure, PanelsHeatMapAndColorBarInPlace) {
  FigureImages images = BrighterBlock();
  Picture figure = ComparisonFigure(images, "The noon view");
  Panels p = FindPanels(figure, images);
  ASSERT_EQ(p.map.Width(), kW) << p.map;
  ASSERT_EQ(p.map.Height(), kH) << p.map;
  EXPECT_EQ(BoxOf(figure, HeatColor(0.5)), Moved(kBlock, p.map.x0, p.map.y0));

  ASSERT_NE(p.frame, p.block);
  EXPECT_EQ(p.frames.y0, p.map.y0);
  EXPECT_EQ(p.frames.y1, p.map.y1);
  ASSERT_GT(p.frames.Width(), 2 * kW) << p.frames << ": the 3D and the 4D panel";
  EXPECT_LT(p.frames.x1, p.map.x0) << p.frames;
  EXPECT_EQ(BoxOf(figure, p.block), Moved(kBlock, p.frames.x0, p.frames.y0)) << "in the 3D panel, left";

  // The colour bar, right of the map: the top of the scale at its top, 0 at its bottom, with ticks.
  Box right_of_map{p.map.x1, p.map.y0, figure.width, p.map.y1};
  Box top = BoxOf(figure, HeatColor(1.0 - 0.5 / kH), right_of_map);
  Box bottom = BoxOf(figure, HeatColor(0.5 / kH), right_of_map);
  EXPECT_EQ(top.y0, p.map.y0);
  EXPECT_EQ(bottom.y1, p.map.y1);
  EXPECT_EQ(top.x0, bottom.x0);
  EXPECT_EQ(figure.At(top.x1, top.y0), kInk) << "the top tick";
  EXPECT_EQ(figure.At(bottom.x1, bottom.y0), kInk) << "the bottom tick";
}

// The title above all; each panel's label above it; the colour bar's numbers at its top, middle
// and bottom.
TEST(ComparisonFigure, LabelsAreDrawnInTheirPlaces) {
  FigureImages images = BrighterBlock();
  Picture figure = ComparisonFigure(images, "The noon view");
  Panels p = FindPanels(figure, images);
  ASSERT_FALSE(p.map.Empty() || p.frames.Empty());
  Box title = Changed(figure, ComparisonFigure(images, ""));
  EXPECT_GT(title.Width(), 50) << title;
  EXPECT_LT(title.y1, p.map.y0 - 15) << title << " above the panels' labels";
  for (int panel_x : {p.frames.x0, p.frames.x1 - kW, p.map.x0})
    EXPECT_GT(Drawn(figure, {panel_x, title.y1, panel_x + kW, p.map.y0}), 20) << "above the panel at x " << panel_x;
  int bar_right = BoxOf(figure, HeatColor(0.5 / kH), {p.map.x1, p.map.y0, figure.width, p.map.y1}).x1;
  for (int y : {p.map.y0, (p.map.y0 + p.map.y1) / 2, p.map.y1 - 1})
    EXPECT_GT(Drawn(figure, {bar_right + 5, y - 3, figure.width, y + 4}), 5) << "a number at y " << y;
}

}  // namespace
}  // namespace aerial::bench
