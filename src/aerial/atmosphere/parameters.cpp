#include "aerial/atmosphere.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace aerial {

double DensityProfileLayer::Density(double altitude_m) const {
  double density = exp_term * std::exp(exp_scale_per_m * altitude_m) +
                   linear_term_per_m * altitude_m + constant_term;
  return std::clamp(density, 0.0, 1.0);
}

double DensityProfile::Density(double altitude_m) const {
  return altitude_m < layers[0].width_m ? layers[0].Density(altitude_m)
                                        : layers[1].Density(altitude_m);
}

AtmosphereParameters AtmosphereParameters::Earth() {
  AtmosphereParameters a;
  a.name = "earth";
  a.wavelengths_nm = {680.0, 550.0, 440.0};
  a.solar_irradiance = {1.474, 1.8504, 1.91198};
  a.sun_angular_radius_rad = 0.004675;
  a.bottom_radius_m = 6360e3;
  a.top_radius_m = 6420e3;
  // Rayleigh: 1.24062e-6 m^-1 * lambda(um)^-4 (Bruneton 2017 demo), scale height 8 km.
  for (int i = 0; i < 3; ++i) {
    double lambda_um = a.wavelengths_nm[i] * 1e-3;
    a.rayleigh_scattering[i] = 1.24062e-6 / std::pow(lambda_um, 4.0);
  }
  a.rayleigh_density.layers[1] = {0.0, 1.0, -1.0 / 8000.0, 0.0, 0.0};
  // Mie: extinction 4.44e-6 m^-1, single-scattering albedo 0.9, scale height 1.2 km, g = 0.8.
  a.mie_extinction = {4.44e-6, 4.44e-6, 4.44e-6};
  a.mie_scattering = {3.996e-6, 3.996e-6, 3.996e-6};
  a.mie_density.layers[1] = {0.0, 1.0, -1.0 / 1200.0, 0.0, 0.0};
  a.mie_phase_g = 0.8;
  // Ozone: tent from 10 km up to a peak at 25 km and down to 0 at 40 km.
  a.absorption_density.layers[0] = {25e3, 0.0, 0.0, 1.0 / 15e3, -2.0 / 3.0};
  a.absorption_density.layers[1] = {0.0, 0.0, 0.0, -1.0 / 15e3, 8.0 / 3.0};
  a.absorption_extinction = {6.50e-7, 1.881e-6, 8.50e-8};
  a.ground_albedo = {0.1, 0.1, 0.1};
  a.mu_s_min = -0.5;  // sun zenith up to 120 degrees.
  return a;
}

namespace {
struct Fnv1a {
  uint64_t state = 1469598103934665603ull;
  void Add(double value) {
    unsigned char bytes[sizeof(double)];
    std::memcpy(bytes, &value, sizeof(double));
    for (unsigned char b : bytes) state = (state ^ b) * 1099511628211ull;
  }
  void Add(const Spectrum& s) {
    for (double v : s) Add(v);
  }
  void Add(const DensityProfile& p) {
    for (const auto& l : p.layers) {
      for (double v : {l.width_m, l.exp_term, l.exp_scale_per_m, l.linear_term_per_m,
                       l.constant_term})
        Add(v);
    }
  }
};
}  // namespace

uint64_t AtmosphereParameters::Hash() const {
  Fnv1a h;
  h.Add(wavelengths_nm);
  h.Add(solar_irradiance);
  h.Add(sun_angular_radius_rad);
  h.Add(bottom_radius_m);
  h.Add(top_radius_m);
  h.Add(rayleigh_density);
  h.Add(rayleigh_scattering);
  h.Add(mie_density);
  h.Add(mie_scattering);
  h.Add(mie_extinction);
  h.Add(mie_phase_g);
  h.Add(absorption_density);
  h.Add(absorption_extinction);
  h.Add(ground_albedo);
  h.Add(mu_s_min);
  return h.state;
}

}  // namespace aerial
