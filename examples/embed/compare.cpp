// Compares the example's frame with another rendering of the same scene (aerial render's),
// separately over the pixels where the example drew a mesh (finite "distance" channel, exr_io.h)
// and over the sky's, and fails when a pixel of either kind differs by more than that kind's
// bound. For each kind it prints
//  - the relative RMSE, sqrt(sum (a - b)^2 / sum b^2) over the pixels' R, G and B;
//  - the largest per-pixel relative error, max_c |a_c - b_c| / max_c b_c, and where it is.
//   embed_compare EMBED.exr REFERENCE.exr MESH_BOUND SKY_BOUND
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "exr_io.h"

namespace {

struct Difference {
  size_t pixels = 0;
  double sum_squared = 0.0, sum_reference = 0.0;
  double max_relative = 0.0;
  int max_x = -1, max_y = -1;

  void Add(const float* a, const float* b, int x, int y) {
    ++pixels;
    double largest = 0.0, reference = 0.0;
    for (int c = 0; c < 3; ++c) {
      double d = double(a[c]) - double(b[c]);
      sum_squared += d * d;
      sum_reference += double(b[c]) * b[c];
      largest = std::max(largest, std::abs(d));
      reference = std::max(reference, double(b[c]));
    }
    double relative = largest / reference;
    if (!(relative <= max_relative)) {  // a NaN counts as the largest
      max_relative = relative;
      max_x = x;
      max_y = y;
    }
  }

  // Energy-weighted, as aerial's tests compute it (EnergyWeightedRelativeRmse,
  // src/aerial/validation/image_metrics.h): this example builds against the installed package alone.
  double RelativeRmse() const { return std::sqrt(sum_squared / sum_reference); }

  bool Report(const char* kind, double bound) const {
    bool ok = pixels > 0 && max_relative <= bound;
    std::printf("%-5s pixels: %6zu, relative RMSE %.3e, max per-pixel relative error %.3e", kind, pixels,
                RelativeRmse(), max_relative);
    if (max_relative != 0.0) std::printf(" at (%d, %d)", max_x, max_y);
    std::printf(", bound %.1e: %s\n", bound, ok ? "ok" : "FAILED");
    return ok;
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: embed_compare EMBED.exr REFERENCE.exr MESH_BOUND SKY_BOUND\n");
    return 2;
  }
  try {
    RgbdImage embed = ReadExr(argv[1]), reference = ReadExr(argv[2]);
    if (embed.width != reference.width || embed.height != reference.height) {
      std::fprintf(stderr, "embed_compare: %dx%d against %dx%d\n", embed.width, embed.height, reference.width,
                   reference.height);
      return 1;
    }
    Difference mesh, sky;
    for (int y = 0; y < embed.height; ++y) {
      for (int x = 0; x < embed.width; ++x) {
        size_t i = 4 * (size_t(y) * embed.width + x);
        bool on_mesh = std::isfinite(embed.rgbd[i + 3]);
        (on_mesh ? mesh : sky).Add(&embed.rgbd[i], &reference.rgbd[i], x, y);
      }
    }
    bool mesh_ok = mesh.Report("mesh", std::stod(argv[3]));
    bool sky_ok = sky.Report("sky", std::stod(argv[4]));
    return mesh_ok && sky_ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "embed_compare: %s\n", e.what());
    return 1;
  }
}
