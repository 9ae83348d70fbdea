#include "aerial/export/fog_density.h"

#include <algorithm>

namespace aerial {

double Luma(const glm::dvec3& rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

AirCoefficients AirCoefficientsAt(const AtmosphereParameters& atmosphere, const glm::dvec3& point) {
  const double radius = atmosphere.bottom_radius_m;
  const double above_sea_level = glm::length(point - glm::dvec3(0.0, 0.0, -radius)) - radius;
  if (above_sea_level > atmosphere.top_radius_m - radius) return {glm::dvec3(0.0), glm::dvec3(0.0)};
  const double altitude = std::max(above_sea_level, 0.0);
  const double rayleigh = atmosphere.rayleigh_density.Density(altitude);
  const double mie = atmosphere.mie_density.Density(altitude);
  const double absorption = atmosphere.absorption_density.Density(altitude);
  AirCoefficients air;
  for (int c = 0; c < 3; ++c) {
    air.scattering[c] = atmosphere.rayleigh_scattering[c] * rayleigh + atmosphere.mie_scattering[c] * mie;
    air.absorption[c] = (atmosphere.mie_extinction[c] - atmosphere.mie_scattering[c]) * mie +
                        atmosphere.absorption_extinction[c] * absorption;
  }
  return air;
}

double FogDensity(const AtmosphereParameters& atmosphere, const glm::dvec3& point) {
  const AirCoefficients air = AirCoefficientsAt(atmosphere, point);
  return Luma(air.scattering + air.absorption);
}

}  // namespace aerial
