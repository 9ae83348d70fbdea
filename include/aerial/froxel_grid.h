#pragma once
// The froxel grid's shape: resolution across the screen and in depth, and how far it reaches.
// Its depth slices: slice k's center stands for the distance far * ((k + 0.5) / depth)^2
// (quadratic, thin near slices). SliceDistance and DepthCoordinate are that mapping's only C++
// definition; shaders/include/froxel_depth.glsl is its only GLSL one (and says why quadratic).
#include <string>

namespace aerial {

struct FroxelGrid {
  int width = 32;
  int height = 32;
  int depth = 32;
  double far_m = 128e3;  // Hillaire 2020: 32 slices of up to 4 km reach ~128 km

  // "WxHxD", e.g. "32x32x32"; throws aerial::Error naming `field` for anything else or for a
  // resolution outside [2, 256].
  static FroxelGrid Parse(const std::string& text, const std::string& field = "FroxelGrid::width/height/depth");
  void Validate() const;

  double SliceDistance(double slice_center) const;  // distance of a (fractional) slice center
  double DepthCoordinate(double distance) const;    // texture z in [0, 1] for a distance
  std::string Describe() const;                     // "32x32x32, quadratic to 128 km"
};

}  // namespace aerial
