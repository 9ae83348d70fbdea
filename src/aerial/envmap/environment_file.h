#pragma once
// An environment map as an OpenEXR file: float R, G, B, A linear radiance (W/m^2/sr/nm), the
// "envmap" attribute (lat-long or cube) and aerial's own attributes, which say where the sun is
// and what it gives, so that a renderer can light the scene with a separate sun lamp when the
// disc is left out of the map:
//   aerial:layout, aerial:frame            strings: the texels' directions, in words
//   aerial:channels                        string: what R, G and B hold
//   aerial:altitude_m                      float
//   aerial:sun_direction                   v3f, unit vector toward the sun (scene frame)
//   aerial:sun_zenith_deg, aerial:sun_azimuth_deg, aerial:sun_angular_diameter_deg   floats
//   aerial:sun_disc                        string: "in the map" or "left out"
//   aerial:sun_irradiance                  v3f, W/m^2/nm on a surface facing the sun, per channel
//   aerial:sun_illuminance_lux             float, the same as illuminance
//   aerial:sun_from                        string, when the sun came from a date and a place
#include <filesystem>
#include <string>

#include "aerial/envmap/environment_map.h"
#include "aerial/image/exr.h"

namespace aerial {

struct EnvironmentDescription {
  std::string channels;  // what the tables' three channels hold, in words
  double sun_angular_radius_rad = 0.0;
  std::string sun_from;  // the date, time and place the sun came from, or empty
};

ExrHeaderExtras EnvironmentHeader(const EnvironmentMap& map, const EnvironmentMapOptions& options,
                                  const EnvironmentDescription& description);

// Encodes and writes atomically (core/atomic_file.h); throws Error naming the path on failure.
void WriteEnvironmentExr(const std::filesystem::path& path, const EnvironmentMap& map,
                         const ExrHeaderExtras& header);

}  // namespace aerial
