#include "aerial/bench/comparison_figure.h"

#include <algorithm>
#include <cmath>

#include "aerial/bench/cairo_figure.h"
#include "aerial/bench/color_bar.h"
#include "aerial/bench/figure_label.h"
#include "aerial/bench/heatmap.h"
#include "aerial/image.h"
#include "aerial/image/exposure.h"

namespace aerial::bench {

using validation::ErrorMap;
namespace {

constexpr int kMargin = 12, kGap = 10, kBarWidth = 16;

ImageRgbF AverageBlocks(const ImageRgbF& image, int k) {
  ImageRgbF out{image.width / k, image.height / k, {}};
  out.rgba.assign(size_t(out.width) * size_t(out.height) * 4, 0.0f);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      float* o = out.pixel(x, y);
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i)
          for (int c = 0; c < 3; ++c) o[c] += image.pixel(x * k + i, y * k + j)[c] / float(k * k);
      o[3] = 1.0f;
    }
  return out;
}

std::vector<float> MaxBlocks(const std::vector<float>& values, int width, int height, int k) {
  int w = width / k, h = height / k;
  std::vector<float> out(size_t(w) * size_t(h), 0.0f);
  for (int y = 0; y < h * k; ++y)
    for (int x = 0; x < w * k; ++x) {
      float& o = out[size_t(y / k) * size_t(w) + size_t(x / k)];
      o = std::max(o, values[size_t(y) * size_t(width) + size_t(x)]);
    }
  return out;
}

double Percentile(std::vector<float> values, double p) {
  auto at = values.begin() + std::ptrdiff_t(p * double(values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

}  // namespace

Picture ComparisonFigure(const FigureImages& images, const std::string& title) {
  int k = (images.lut4d.width + kMaxPanelWidth - 1) / kMaxPanelWidth;
  ImageRgbF small3d = AverageBlocks(images.lut3d, k), small4d = AverageBlocks(images.lut4d, k);
  int w = small4d.width, h = small4d.height;
  ToneMapOptions tone{.exposure = Exposure{}.MultiplierFor(small4d)};  // metered, as PNG images are
  std::vector<float> error = MaxBlocks(ErrorMap(images.lut3d, images.lut4d, images.surface),
                                       images.lut4d.width, images.lut4d.height, k);
  // The 99th percentile, rounded up to a readable number: a few hot pixels do not wash out the map.
  double scale_max = NiceCeiling(std::max(Percentile(error, 0.99), 1e-4));

  int text_h = int(std::ceil(LabelHeight()));
  int label_y = kMargin + text_h + kGap, panel_y = label_y + text_h + kGap / 2;
  int bar_x = kMargin + 3 * w + 2 * kGap + kGap;
  CairoFigure figure(bar_x + ColorBarWidth(kBarWidth, scale_max) + kMargin, panel_y + h + kMargin);
  cairo_t* cr = figure.cr();
  DrawLabel(cr, title, kMargin, kMargin);
  const char* labels[] = {"3D tables", "4D tables", "Relative difference"};
  for (int i = 0; i < 3; ++i) DrawLabel(cr, labels[i], kMargin + i * (w + kGap), label_y);
  DrawPixels(cr, kMargin, panel_y, ToneMapToSrgb8(small3d, tone), w, h);
  DrawPixels(cr, kMargin + w + kGap, panel_y, ToneMapToSrgb8(small4d, tone), w, h);
  DrawPixels(cr, kMargin + 2 * (w + kGap), panel_y, HeatMapRgba8(error, scale_max), w, h);
  DrawColorBar(cr, bar_x, panel_y, kBarWidth, h, scale_max);
  return figure.Finish();
}

}  // namespace aerial::bench
