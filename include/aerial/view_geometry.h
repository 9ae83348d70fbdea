#pragma once
// A camera, a view ray and the sun as users give them (altitude, zenith angles, relative azimuth)
// and as the tables index them (r, mu, mu_s, nu).
#include "aerial/atmosphere.h"

namespace aerial {

struct ViewAngles {
  double altitude_m = 0.0;
  double view_zenith_deg = 0.0;
  double sun_zenith_deg = 0.0;
  double azimuth_deg = 0.0;  // between the horizontal parts of view and sun; 0: toward the sun
};

struct RayParameters {
  double r, mu, mu_s, nu;
};

// Throws aerial::Error for an altitude outside [0, top - bottom] or angles out of range.
void ValidateViewAngles(const ViewAngles& view, const AtmosphereParameters& atmosphere);

// nu = mu mu_s + sqrt(1 - mu^2) sqrt(1 - mu_s^2) cos(azimuth) (spherical law of cosines).
RayParameters ToRayParameters(const ViewAngles& view, const AtmosphereParameters& atmosphere);

}  // namespace aerial
