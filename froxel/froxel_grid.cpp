#include "aerial/froxel_grid.h"

#include <cmath>
#include <cstdio>
#include <regex>

#include "aerial/core/toml_reader.h"
#include "aerial/error.h"

namespace aerial {

FroxelGrid FroxelGrid::Parse(const std::string& text, const std::string& field) {
  static const std::regex pattern(R"((\d{1,4})x(\d{1,4})x(\d{1,4}))");
  std::smatch match;
  if (!std::regex_match(text, match, pattern))
    throw Error(field, text, "WxHxD with integers in [2, 256], e.g. 32x32x32");
  FroxelGrid grid;
  grid.width = std::stoi(match[1]);
  grid.height = std::stoi(match[2]);
  grid.depth = std::stoi(match[3]);
  try {
    grid.Validate();
  } catch (const Error&) {
    throw Error(field, text, "WxHxD with integers in [2, 256], e.g. 32x32x32");
  }
  return grid;
}

void FroxelGrid::Validate() const {
  for (int n : {width, height, depth}) {
    if (n < 2 || n > 256)
      throw Error("FroxelGrid::width/height/depth",
                  std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(depth),
                  "each of W, H, D in [2, 256]");
  }
  if (!(far_m > 100.0 && far_m <= 1e6))
    throw Error("FroxelGrid::far_m", TomlFloat(far_m), "meters in (100, 1e6]");
}

double FroxelGrid::SliceDistance(double slice_center) const {
  double s = slice_center / depth;
  return far_m * s * s;
}

double FroxelGrid::DepthCoordinate(double distance) const {
  return std::sqrt(std::max(distance, 0.0) / far_m);
}

std::string FroxelGrid::Describe() const {
  char text[96];
  std::snprintf(text, sizeof text, "%dx%dx%d, quadratic slices to %.0f km", width, height, depth,
                far_m / 1000.0);
  return text;
}

}  // namespace aerial
