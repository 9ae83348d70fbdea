#pragma once
// The figure of one view: the 3D and 4D frames side by side, tone-mapped with one exposure, and
// their relative difference (image_metrics.h ErrorMap) as a heat map with a labelled colour bar.
#include <string>

#include "aerial/bench/bench_results.h"
#include "aerial/bench/picture.h"

namespace aerial::bench {

// Panels at most this wide: larger frames are reduced by an integer factor, the frames by
// averaging and the difference by its maximum over each block (no error is hidden).
inline constexpr int kMaxPanelWidth = 480;

// title goes above the panels.
Picture ComparisonFigure(const FigureImages& images, const std::string& title);

}  // namespace aerial::bench
