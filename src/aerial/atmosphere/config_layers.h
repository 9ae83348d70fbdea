#pragma once
// Density layers as atmosphere files write them, shared by config.cpp (reading, Validate) and
// config_toml_writer.cpp (ToToml); see config.h for the format.
#include <utility>
#include <vector>

#include "aerial/atmosphere.h"

namespace aerial::config_layers {

using Layer = DensityProfileLayer;

// The members of a density layer, in file order, with their TOML keys.
inline constexpr std::pair<const char*, double Layer::*> kFields[] = {
    {"width_m", &Layer::width_m},
    {"exp_term", &Layer::exp_term},
    {"exp_scale_per_m", &Layer::exp_scale_per_m},
    {"linear_term_per_m", &Layer::linear_term_per_m},
    {"constant_term", &Layer::constant_term}};

// The layers as the file lists them: only layers[1] when layers[0] is the zero placeholder.
inline std::vector<const Layer*> FileLayers(const DensityProfile& profile) {
  for (auto [key, member] : kFields)
    if (profile.layers[0].*member != 0.0) return {&profile.layers[0], &profile.layers[1]};
  return {&profile.layers[1]};
}

}  // namespace aerial::config_layers
