#pragma once
// The sky-view table's size and its correction lattice's, for the images the renderer allocates.
// The lattice's shape comes from shaders/include/sky_view_lattice.glsl, the lines the shaders
// compile; the shaders take the table's size from its image.
#include <array>

namespace aerial {

#include "shaders/include/sky_view_lattice.glsl"

// Hillaire 2020's 192x108: azimuth over [0, pi], zenith split at the horizon (54 rows each side).
constexpr std::array<int, 2> kSkyViewSize = {192, 108};
constexpr std::array<int, 2> kSkyViewLatticeSize = {GetSkyViewLatticeWidth(kSkyViewSize[0]),
                                                     GetSkyViewLatticeHeight(kSkyViewSize[1])};

// The lattice is made in bands of whole rows, each for the camera altitude of its own frame
// (frame_cache_policy.h, SkyViewLatticeBandsToRemake): 8 bands of 5 rows (the last one of 3).
inline constexpr int kSkyViewLatticeBands = 8;
inline constexpr int kSkyViewLatticeBandRows = (kSkyViewLatticeSize[1] + kSkyViewLatticeBands - 1) / kSkyViewLatticeBands;

// The lattice rows [first, end) of band b.
struct LatticeRows {
  int first = 0, end = 0;
};
constexpr LatticeRows SkyViewLatticeBandRows(int band) {
  int first = band * kSkyViewLatticeBandRows;
  int end = first + kSkyViewLatticeBandRows;
  return {first, end < kSkyViewLatticeSize[1] ? end : kSkyViewLatticeSize[1]};
}
static_assert(SkyViewLatticeBandRows(kSkyViewLatticeBands - 1).first < kSkyViewLatticeSize[1],
              "every band holds a row");

}  // namespace aerial
