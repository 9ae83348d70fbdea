#include "aerial/bench/comparison_figure.h"

#include <algorithm>
#include <cmath>

#include "aerial/bench/heatmap.h"
#include "aerial/image.h"
#include "aerial/image/exposure.h"

namespace aerial::bench {

using validation::ErrorMap;
namespace {

constexpr int kMargin = 12, kGap = 10, kTextScale = 2, kBarWidth = 16;
constexpr Rgb kPaper{255, 255, 255}, kInk{20, 20, 20};

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

Canvas ComparisonFigure(const FigureImages& images, const std::string& title) {
  int k = (images.lut4d.width + kMaxPanelWidth - 1) / kMaxPanelWidth;
  ImageRgbF small3d = AverageBlocks(images.lut3d, k), small4d = AverageBlocks(images.lut4d, k);
  int w = small4d.width, h = small4d.height;
  ToneMapOptions tone{.exposure = Exposure{}.MultiplierFor(small4d)};  // metered, as PNG images are
  std::vector<float> error = MaxBlocks(ErrorMap(images.lut3d, images.lut4d, images.surface),
                                       images.lut4d.width, images.lut4d.height, k);
  // The 99th percentile, rounded up to a readable number: a few hot pixels do not wash out the map.
  double scale_max = NiceCeiling(std::max(Percentile(error, 0.99), 1e-4));

  int text_h = Canvas::TextHeight(kTextScale);
  int label_y = kMargin + text_h + kGap, panel_y = label_y + text_h + kGap / 2;
  int bar_x = kMargin + 3 * w + 2 * kGap + kGap;
  int width = bar_x + ColorBarWidth(kBarWidth, scale_max, kTextScale) + kMargin;
  Canvas canvas(width, panel_y + h + kMargin, kPaper);
  canvas.Text(kMargin, kMargin, title, kTextScale, kInk);
  const char* labels[] = {"3D TABLES", "4D TABLES", "RELATIVE DIFFERENCE"};
  for (int i = 0; i < 3; ++i) canvas.Text(kMargin + i * (w + kGap), label_y, labels[i], kTextScale, kInk);
  canvas.Blit(kMargin, panel_y, ToneMapToSrgb8(small3d, tone), w, h);
  canvas.Blit(kMargin + w + kGap, panel_y, ToneMapToSrgb8(small4d, tone), w, h);
  DrawHeatMap(canvas, kMargin + 2 * (w + kGap), panel_y, error, w, h, scale_max);
  DrawColorBar(canvas, bar_x, panel_y, kBarWidth, h, scale_max, kTextScale);
  return canvas;
}

}  // namespace aerial::bench
