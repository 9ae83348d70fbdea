#include "aerial/envmap/environment_file.h"

#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <numbers>
#include <thread>

#include "aerial/core/atomic_file.h"
#include "aerial/image/exposure.h"
#include "aerial/version.h"

namespace aerial {
namespace {

std::array<float, 3> ToFloats(const glm::dvec3& v) { return {float(v.x), float(v.y), float(v.z)}; }

}  // namespace

ExrHeaderExtras EnvironmentHeader(const EnvironmentMap& map, const EnvironmentMapOptions& options,
                                  const EnvironmentDescription& description) {
  ExrHeaderExtras header;
  const bool lat_long = options.layout == EnvironmentLayout::kLatLong;
  header.envmap = lat_long ? ExrHeaderExtras::Envmap::kLatLong : ExrHeaderExtras::Envmap::kCube;
  auto& a = header.attributes;
  a["aerial:version"] = std::string(AERIAL_VERSION);
  a["aerial:frame"] = std::string(
      "scene frame: x east, y north, z up (the point's vertical); in OpenEXR's envmap frame X north, Y up, Z east");
  a["aerial:layout"] = std::string(
      lat_long ? "lat-long: texel (x, y) looks at zenith angle 180 (y + 0.5) / height degrees and compass azimuth "
                 "360 (x + 0.5) / width - 90 degrees: top row the zenith, centre column east, north at a quarter "
                 "of the width (Blender's equirectangular convention in a Z-up world with +x east)"
               : "cube: OpenEXR's cube envmap (ImfEnvmap.h) in the frame X north, Y up, Z east");
  a["aerial:channels"] = description.channels;
  a["aerial:altitude_m"] = float(options.altitude_m);
  a["aerial:sun_direction"] = ToFloats(options.sun.Direction());
  a["aerial:sun_zenith_deg"] = float(options.sun.zenith_deg);
  a["aerial:sun_azimuth_deg"] = float(options.sun.azimuth_deg);
  a["aerial:sun_angular_diameter_deg"] = float(2.0 * description.sun_angular_radius_rad * 180.0 / std::numbers::pi);
  a["aerial:sun_disc"] = std::string(options.sun_disc ? "in the map"
                                                      : "left out: light the scene with a sun lamp of "
                                                        "aerial:sun_irradiance toward aerial:sun_direction");
  const std::array<double, 3>& e = map.sun_irradiance;
  a["aerial:sun_irradiance"] = std::array<float, 3>{float(e[0]), float(e[1]), float(e[2])};
  a["aerial:sun_illuminance_lux"] = float(kLuminancePerChannel[0] * e[0] + kLuminancePerChannel[1] * e[1] +
                                          kLuminancePerChannel[2] * e[2]);
  if (!description.sun_from.empty()) a["aerial:sun_from"] = description.sun_from;
  return header;
}

void WriteEnvironmentExr(const std::filesystem::path& path, const EnvironmentMap& map, const ExrHeaderExtras& header) {
  // OpenEXR compresses a file's blocks on its global thread pool, which has no threads unless
  // asked: a 2048 x 1024 map took most of a second to compress on one. A caller that chose a
  // count keeps it.
  if (Imf::globalThreadCount() == 0) Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency())));
  WriteFileAtomically(path, EncodeExr(map.image, header));
}

}  // namespace aerial
