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

}  // namespace aerial
