#pragma once
// The reference point: Bruneton 2017's OpenGL precompute of the same tables (4 orders, float32,
// separate textures, transmittance 256x64, irradiance 64x16, scattering 32x128x32x8) on llvmpipe
// on this kind of machine (2 cores), measured once (docs/speed.md); that code cannot run here (no
// OpenGL context in this setup), so the figures are
// constants and the benchmark compares against them as ratios, which survive the machine's noise
// better than absolute times.
#include <array>
#include <string>
#include <string_view>

namespace aerial::bench {

struct ReferenceStep {
  std::string_view name;
  double seconds;
};

inline constexpr double kBruneton2017TotalSeconds = 41.4;
inline constexpr std::array<ReferenceStep, 5> kBruneton2017Steps = {{
    {"scattering density", 38.4},  // 93 % of the total, 12.8 s per order
    {"multiple scattering", 2.3},
    {"single scattering", 0.47},
    {"indirect irradiance", 0.15},
    {"transmittance", 0.02},
}};

// Whether a device is the kind the figures above were taken on (Mesa's llvmpipe, which lavapipe
// reports): a speed-up against them on another device (a GPU) would compare two machines, not two
// programs.
bool IsBruneton2017Device(const std::string& device);

// The Bruneton step that one of our passes belongs to, or "" if none. Our density is split in
// "incident radiance" + "scattering density", and our multiple scattering is followed by a
// separate "accumulate" pass, so each pair maps to one Bruneton step. Direct irradiance has no
// figure there (negligible): it counts in our total only.
std::string Bruneton2017Step(const std::string& pass);

}  // namespace aerial::bench
