#include "aerial/viewer/atmosphere_knobs.h"

namespace aerial::viewer {
namespace {

std::optional<double> ScaleHeight(const DensityProfile& profile) {
  for (int i = 1; i >= 0; --i) {
    const DensityProfileLayer& layer = profile.layers[i];
    if (layer.exp_term != 0.0 && layer.exp_scale_per_m < 0.0) return -1.0 / layer.exp_scale_per_m;
  }
  return std::nullopt;
}

void SetScaleHeight(DensityProfile& profile, std::optional<double> height_m) {
  if (!height_m) return;
  for (DensityProfileLayer& layer : profile.layers)
    if (layer.exp_term != 0.0) layer.exp_scale_per_m = -1.0 / *height_m;
}

}  // namespace

AtmosphereKnobs ReadKnobs(const AtmosphereParameters& base) {
  const Spectrum& albedo = base.ground_albedo;
  return {.rayleigh_scale_height_m = ScaleHeight(base.rayleigh_density),
          .mie_scale_height_m = ScaleHeight(base.mie_density),
          .mie_g = base.mie_phase_g,
          .ozone_scale = 1.0,
          .ground_albedo = (albedo[0] + albedo[1] + albedo[2]) / 3.0};
}

AtmosphereParameters ApplyKnobs(const AtmosphereParameters& base, const AtmosphereKnobs& knobs) {
  const AtmosphereKnobs unchanged = ReadKnobs(base);
  AtmosphereParameters a = base;
  if (knobs.rayleigh_scale_height_m != unchanged.rayleigh_scale_height_m)
    SetScaleHeight(a.rayleigh_density, knobs.rayleigh_scale_height_m);
  if (knobs.mie_scale_height_m != unchanged.mie_scale_height_m)
    SetScaleHeight(a.mie_density, knobs.mie_scale_height_m);
  a.mie_phase_g = knobs.mie_g;
  if (knobs.ozone_scale != unchanged.ozone_scale)
    for (double& k : a.absorption_extinction) k *= knobs.ozone_scale;
  if (knobs.ground_albedo != unchanged.ground_albedo)
    a.ground_albedo = {knobs.ground_albedo, knobs.ground_albedo, knobs.ground_albedo};
  return a;
}

}  // namespace aerial::viewer
