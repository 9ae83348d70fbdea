#include "aerial/bench/chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "aerial/bench/cairo_figure.h"
#include "aerial/bench/figure_label.h"
#include "aerial/error.h"

namespace aerial::bench {
namespace {

constexpr int kMargin = 14, kTick = 5;
constexpr Rgb kGrid{225, 225, 225};

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

// (x, y) is the marker's centre; a square covers whole pixels.
void Marker(cairo_t* cr, const ChartSeries& s, double x, double y) {
  if (s.square_markers) {
    FillRect(cr, std::floor(x) - 4, std::floor(y) - 4, 9, 9, s.color);
  } else {
    SetColor(cr, s.color);
    cairo_arc(cr, x, y, 5.0, 0.0, 2.0 * std::numbers::pi);
    cairo_fill(cr);
  }
}

// Through points in order, 2 pixels wide.
void Polyline(cairo_t* cr, const std::vector<std::array<double, 2>>& points, Rgb color) {
  SetColor(cr, color);
  for (auto [x, y] : points) cairo_line_to(cr, x, y);
  cairo_set_line_width(cr, 2.0);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke(cr);
}

}  // namespace

Picture LogLogChart(const ChartSpec& spec, int width, int height) {
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

  double text_h = LabelHeight();
  double y_label_w = 0.0;
  for (double v : y_axis.Ticks()) y_label_w = std::max(y_label_w, LabelWidth(FormatNumber(v)));
  // The last x label is centered on the right end of the axis: leave room for its half.
  double x_label_half = LabelWidth(FormatNumber(std::pow(10.0, x_axis.hi))) / 2;
  int left = int(std::ceil(kMargin + y_label_w + kTick + 4)), right = int(width - kMargin - x_label_half);
  int top = int(std::ceil(kMargin + 2 * (text_h + 10))), bottom = int(height - kMargin - 2 * text_h - 16);
  // A value's place: the centre of a pixel at each end of an axis.
  auto px = [&](double x) { return left + 0.5 + x_axis.Fraction(x) * (right - left); };
  auto py = [&](double y) { return bottom + 0.5 - y_axis.Fraction(y) * (bottom - top); };

  CairoFigure figure(width, height);
  cairo_t* cr = figure.cr();
  DrawLabel(cr, spec.title, kMargin, kMargin);
  DrawLabel(cr, spec.y_label, kMargin, kMargin + text_h + 10);
  DrawLabel(cr, spec.x_label, (left + right) / 2.0, height - kMargin, {0.5, 1.0});
  for (double v : x_axis.Ticks()) {
    double x = std::floor(px(v));
    FillRect(cr, x, top, 1, bottom - top, kGrid);
    FillRect(cr, x, bottom, 1, kTick, kInk);
    DrawLabel(cr, FormatNumber(v), x + 0.5, bottom + kTick + 4, {0.5, 0.0});
  }
  for (double v : y_axis.Ticks()) {
    double y = std::floor(py(v));
    FillRect(cr, left, y, right - left, 1, kGrid);
    FillRect(cr, left - kTick, y, kTick, 1, kInk);
    DrawLabel(cr, FormatNumber(v), left - kTick - 4, y + 0.5, {1.0, 0.5});
  }
  FillRect(cr, left, top, 1, bottom - top + 1, kInk);
  FillRect(cr, left, bottom, right - left, 1, kInk);

  for (const ChartSeries& s : spec.series) {
    std::vector<std::array<double, 2>> points = s.points;
    std::sort(points.begin(), points.end());
    for (auto& [x, y] : points) x = px(x), y = py(y);
    Polyline(cr, points, s.color);
    for (auto [x, y] : points) Marker(cr, s, x, y);
  }

  // Legend, top left inside the plot.
  double legend_w = 0.0;
  for (const ChartSeries& s : spec.series) legend_w = std::max(legend_w, LabelWidth(s.label));
  int row_h = int(std::ceil(text_h)) + 8, box_h = int(spec.series.size()) * row_h + 8;
  int box_x = left + 10, box_y = top + 10, box_w = int(std::ceil(legend_w)) + 44;
  FillRect(cr, box_x, box_y, box_w, box_h, kInk);
  FillRect(cr, box_x + 1, box_y + 1, box_w - 2, box_h - 2, kPaper);
  for (size_t i = 0; i < spec.series.size(); ++i) {
    const ChartSeries& s = spec.series[i];
    double y = box_y + 4 + int(i) * row_h + row_h / 2.0;
    Polyline(cr, {{box_x + 8.0, y}, {box_x + 32.0, y}}, s.color);
    Marker(cr, s, box_x + 20, y);
    DrawLabel(cr, s.label, box_x + 38, y, {0.0, 0.5});
  }
  return figure.Finish();
}

}  // namespace aerial::bench
