#include "aerial/bench/chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "aerial/error.h"

namespace aerial::bench {
namespace {

constexpr int kMargin = 14, kTextScale = 2, kTick = 5;
constexpr Rgb kPaper{255, 255, 255}, kInk{20, 20, 20}, kGrid{225, 225, 225};

std::string FormatNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// A log axis from the decade below the smallest value to the decade above the largest.
struct LogAxis {
  double lo, hi;  // log10 of the ends
  LogAxis(double min, double max)
      : lo(std::floor(std::log10(min))),
        hi(std::max(std::ceil(std::log10(max)), std::floor(std::log10(min)) + 1)) {}
  double Fraction(double v) const { return (std::log10(v) - lo) / (hi - lo); }
  // 1, 2 and 5 times each power of ten in range; only the powers when there are many decades.
  std::vector<double> Ticks() const {
    std::vector<double> ticks;
    for (double d = lo; d <= hi; ++d)
      for (double m : {1.0, 2.0, 5.0}) {
        double v = m * std::pow(10.0, d);
        if ((m == 1.0 || hi - lo <= 3) && std::log10(v) <= hi + 1e-9) ticks.push_back(v);
      }
    return ticks;
  }
};

void Marker(Canvas& canvas, const ChartSeries& s, double x, double y) {
  if (s.square_markers)
    canvas.FillRect(int(std::lround(x)) - 4, int(std::lround(y)) - 4, 9, 9, s.color);
  else
    canvas.Disc(x, y, 5.0, s.color);
}

}  // namespace

Canvas LogLogChart(const ChartSpec& spec, int width, int height) {
  double x_min = INFINITY, x_max = 0.0, y_min = INFINITY, y_max = 0.0;
  for (const ChartSeries& s : spec.series)
    for (auto [x, y] : s.points) {
      if (!(x > 0.0 && y > 0.0 && std::isfinite(x) && std::isfinite(y)))
        throw Error("chart point", FormatNumber(x) + ", " + FormatNumber(y), "positive and finite",
                    spec.title);
      x_min = std::min(x_min, x), x_max = std::max(x_max, x);
      y_min = std::min(y_min, y), y_max = std::max(y_max, y);
    }
  if (x_max == 0.0) throw Error("chart", spec.title, "at least one point");
  LogAxis x_axis(x_min, x_max), y_axis(y_min, y_max);

  int text_h = Canvas::TextHeight(kTextScale);
  int y_label_w = 0;
  for (double v : y_axis.Ticks())
    y_label_w = std::max(y_label_w, Canvas::TextWidth(FormatNumber(v), kTextScale));
  // The last x label is centered on the right end of the axis: leave room for its half.
  int x_label_half = Canvas::TextWidth(FormatNumber(std::pow(10.0, x_axis.hi)), kTextScale) / 2;
  int left = kMargin + y_label_w + kTick + 4, right = width - kMargin - x_label_half;
  int top = kMargin + 2 * (text_h + 10), bottom = height - kMargin - 2 * text_h - 16;
  auto px = [&](double x) { return left + x_axis.Fraction(x) * (right - left); };
  auto py = [&](double y) { return bottom - y_axis.Fraction(y) * (bottom - top); };

  Canvas canvas(width, height, kPaper);
  canvas.Text(kMargin, kMargin, spec.title, kTextScale, kInk);
  canvas.Text(kMargin, kMargin + text_h + 10, spec.y_label, kTextScale, kInk);
  canvas.Text((left + right - Canvas::TextWidth(spec.x_label, kTextScale)) / 2, height - kMargin - text_h,
              spec.x_label, kTextScale, kInk);
  for (double v : x_axis.Ticks()) {
    int x = int(std::lround(px(v)));
    canvas.FillRect(x, top, 1, bottom - top, kGrid);
    canvas.FillRect(x, bottom, 1, kTick, kInk);
    std::string label = FormatNumber(v);
    canvas.Text(x - Canvas::TextWidth(label, kTextScale) / 2, bottom + kTick + 4, label, kTextScale, kInk);
  }
  for (double v : y_axis.Ticks()) {
    int y = int(std::lround(py(v)));
    canvas.FillRect(left, y, right - left, 1, kGrid);
    canvas.FillRect(left - kTick, y, kTick, 1, kInk);
    std::string label = FormatNumber(v);
    canvas.Text(left - kTick - 4 - Canvas::TextWidth(label, kTextScale), y - text_h / 2, label, kTextScale,
                kInk);
  }
  canvas.FillRect(left, top, 1, bottom - top + 1, kInk);
  canvas.FillRect(left, bottom, right - left, 1, kInk);

  for (const ChartSeries& s : spec.series) {
    std::vector<std::array<double, 2>> points = s.points;
    std::sort(points.begin(), points.end());
    for (size_t i = 1; i < points.size(); ++i)
      canvas.Line(px(points[i - 1][0]), py(points[i - 1][1]), px(points[i][0]), py(points[i][1]), 2.0,
                  s.color);
    for (auto [x, y] : points) Marker(canvas, s, px(x), py(y));
  }

  // Legend, top left inside the plot.
  int legend_w = 0;
  for (const ChartSeries& s : spec.series)
    legend_w = std::max(legend_w, Canvas::TextWidth(s.label, kTextScale));
  int row_h = text_h + 8, box_w = legend_w + 44, box_h = int(spec.series.size()) * row_h + 8;
  int box_x = left + 10, box_y = top + 10;
  canvas.FillRect(box_x, box_y, box_w, box_h, kInk);
  canvas.FillRect(box_x + 1, box_y + 1, box_w - 2, box_h - 2, kPaper);
  for (size_t i = 0; i < spec.series.size(); ++i) {
    const ChartSeries& s = spec.series[i];
    int y = box_y + 4 + int(i) * row_h + row_h / 2;
    canvas.Line(box_x + 8, y, box_x + 32, y, 2.0, s.color);
    Marker(canvas, s, box_x + 20, y);
    canvas.Text(box_x + 38, y - text_h / 2, s.label, kTextScale, kInk);
  }
  return canvas;
}

}  // namespace aerial::bench
