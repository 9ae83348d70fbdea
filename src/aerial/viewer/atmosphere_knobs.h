#pragma once
// The atmosphere parameters the viewer's panel edits, as changes to a base atmosphere (the
// built-in "earth" or --atmosphere FILE; aerial/atmosphere.h):
//   - Rayleigh and Mie scale heights H: every density layer with an exponential term gets
//     exp_scale_per_m = -1 / H (density exp(-h / H), Bruneton 2017's DensityProfileLayer);
//   - Mie asymmetry g of the Cornette-Shanks phase function;
//   - ozone: a factor on the base's absorption extinction (0 removes the ozone layer);
//   - ground albedo: one grey Lambertian albedo for the three wavelengths.
#include <optional>

#include "aerial/atmosphere.h"

namespace aerial::viewer {

struct AtmosphereKnobs {
  // Unset when the base profile has no exponential layer (e.g. a file with linear layers only):
  // the panel then does not offer the knob.
  std::optional<double> rayleigh_scale_height_m;
  std::optional<double> mie_scale_height_m;
  double mie_g = 0.8;
  double ozone_scale = 1.0;
  double ground_albedo = 0.1;

  bool operator==(const AtmosphereKnobs&) const = default;
};

// The knobs' values in the base atmosphere (scale heights from its upper layer with an
// exponential term; albedo: the mean of the three).
AtmosphereKnobs ReadKnobs(const AtmosphereParameters& base);

// The base atmosphere with the knobs applied. Only knobs that differ from ReadKnobs(base) change
// anything, so ApplyKnobs(base, ReadKnobs(base)) is base exactly (and finds its cached tables).
AtmosphereParameters ApplyKnobs(const AtmosphereParameters& base, const AtmosphereKnobs& knobs);

}  // namespace aerial::viewer
