// aerial envmap: the sky seen from one point in every direction, as an HDR environment map for
// image-based lighting in other renderers (src/aerial/envmap/). Every option and path is checked
// before any GPU work; files are written atomically.
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>

#include "aerial/api/impl.h"
#include "aerial/cli/commands.h"
#include "aerial/cli/common_options.h"
#include "aerial/cli/memory_uses.h"
#include "aerial/cli/path_option.h"
#include "aerial/cli/sun_date_options.h"
#include "aerial/core/format_number.h"
#include "aerial/core/output_conflicts.h"
#include "aerial/envmap/environment_file.h"
#include "aerial/error.h"
#include "aerial/image/exposure.h"
#include "aerial/precompute/spectral_precompute.h"
#include "aerial/scene/scene_limits.h"
#include "aerial/view_geometry.h"

namespace aerial::cli {
namespace {

struct EnvmapCommandOptions {
  TableOptions tables;
  double altitude_m = 0.0;
  std::optional<double> sun_zenith_deg, sun_azimuth_deg;
  SunDateOptions sun_date;
  int width = 2048, height = 1024;
  std::string sun_disc = "off";
  std::filesystem::path out, cube_map;
};

// The sun from the angles (scene.h's default sun when neither is given) or from a date.
Sun MakeSun(const EnvmapCommandOptions& options, std::string& sun_from) {
  std::optional<astronomy::SunDate> date = options.sun_date.Make();
  if (!date) {
    Sun sun;
    if (options.sun_azimuth_deg) CheckAzimuthDeg(*options.sun_azimuth_deg, "--sun-azimuth-deg", "command line");
    sun.zenith_deg = options.sun_zenith_deg.value_or(sun.zenith_deg);
    sun.azimuth_deg = options.sun_azimuth_deg.value_or(sun.azimuth_deg);
    return sun;
  }
  if (options.sun_zenith_deg || options.sun_azimuth_deg)
    throw Error("--date", date->date, "no --sun-zenith-deg or --sun-azimuth-deg with it: the date, time and place give "
                "the sun");
  sun_from = date->date + " " + date->time + " " + date->time_zone + " at latitude " +
             FormatNumber(date->latitude_deg) + ", longitude " + FormatNumber(date->longitude_deg) +
             " (geometric, no refraction)";
  return astronomy::SunFromDate(*date, kSunDateOptions, "command line");
}

std::string ChannelsText(const PrecomputeOptions& precompute, const AtmosphereParameters& atmosphere) {
  if (precompute.colour == ColourMode::kSpectral)
    return "linear sRGB (Rec. 709 primaries, D65 white), converted from " +
           std::to_string(precompute.spectral_wavelengths) + " wavelengths";
  return "the radiance at " + FormatNumber(atmosphere.wavelengths_nm[0]) + ", " +
         FormatNumber(atmosphere.wavelengths_nm[1]) + " and " + FormatNumber(atmosphere.wavelengths_nm[2]) + " nm";
}

// The lat-long map, the cube map's six faces (a quarter of the width each) and their encoded
// files: 16 bytes a texel for the directions, the radiance, the image and the encoding each.
std::vector<MemoryUse> EnvmapMemoryUses(const EnvmapCommandOptions& options) {
  uint64_t texels = uint64_t(options.width) * uint64_t(options.height);
  if (!options.cube_map.empty()) texels += 6 * uint64_t(options.width / 4) * uint64_t(options.width / 4);
  return {{"--width/--height", std::to_string(options.width) + "x" + std::to_string(options.height),
           "environment maps, read back and encoded", 64 * texels}};
}

void RunEnvmap(const EnvmapCommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  CheckImageOutputPath(options.out, "--out");
  if (!options.cube_map.empty()) {
    CheckImageOutputPath(options.cube_map, "--cube-map");
    if (options.cube_map.extension() == ".png" || options.cube_map.extension() == ".PNG")
      throw Error("--cube-map", options.cube_map.string(), "an .exr file (OpenEXR's cube environment map)");
  }
  if (options.width != 2 * options.height)
    throw Error("--width/--height", std::to_string(options.width) + "x" + std::to_string(options.height),
                "a lat-long map twice as wide as it is high");
  CheckImageSize(options.width, options.height);
  EnvironmentMapOptions map{.size = options.height, .altitude_m = options.altitude_m,
                            .sun_disc = options.sun_disc == "on"};
  EnvironmentDescription description;
  map.sun = MakeSun(options, description.sun_from);
  AtmosphereParameters atmosphere = options.tables.LoadAtmosphere();
  CheckOutputConflicts({{"--out", options.out}, {"--cube-map", options.cube_map}});
  ValidateViewAngles({.altitude_m = map.altitude_m, .sun_zenith_deg = map.sun.zenith_deg}, atmosphere);

  PrecomputeOptions precompute = options.tables.MakePrecomputeOptions();
  Device device(options.tables.MakeDeviceOptions());
  options.tables.MakeMemoryBudget(device.largest_heap_bytes())
      .Check(Combined(TableMemoryUses(precompute), EnvmapMemoryUses(options)));
  Tables tables = Tables::LoadOrPrecompute(device, atmosphere, precompute, options.tables.MakeLoadOptions());
  const AtmosphereTables& gpu_tables = ImplOf(tables).tables();
  description.channels = ChannelsText(precompute, atmosphere);
  description.sun_angular_radius_rad = atmosphere.sun_angular_radius_rad;

  EnvironmentMap lat_long = RenderEnvironmentMap(gpu_tables, map);
  std::string extension = options.out.extension().string();
  if (extension == ".png" || extension == ".PNG") {
    const std::array<double, 3> white_balance =
        WhiteBalanceForSun(ShaderAtmosphere(atmosphere, precompute).solar_irradiance);
    ToneMapOptions tone_map{.exposure = Exposure{}.MultiplierFor(lat_long.image, white_balance),
                            .white_balance = white_balance};
    WriteImage(options.out, lat_long.image, tone_map);
  } else {
    WriteEnvironmentExr(options.out, lat_long, EnvironmentHeader(lat_long, map, description));
  }
  if (!options.cube_map.empty()) {
    EnvironmentMapOptions cube = map;
    cube.layout = EnvironmentLayout::kCube;
    cube.size = options.width / 4;
    EnvironmentMap faces = RenderEnvironmentMap(gpu_tables, cube);
    WriteEnvironmentExr(options.cube_map, faces, EnvironmentHeader(faces, cube, description));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %s: %dx%d lat-long, sun zenith %.3f deg, azimuth %.3f deg, disc %s; %.2f s\n",
              Printable(options.out.native()).c_str(), options.width, options.height, map.sun.zenith_deg, map.sun.azimuth_deg,
              map.sun_disc ? "in the map" : "left out (aerial:sun_irradiance)", seconds);
}

}  // namespace

void AddEnvmapCommand(CLI::App& app) {
  auto options = std::make_shared<EnvmapCommandOptions>();
  CLI::App* command =
      app.add_subcommand("envmap", "Write the sky seen from one point as an HDR environment map (lat-long EXR)");
  AddPathOption(*command, "--out", options->out,
                "Lat-long map: .exr (linear radiance, with the sun's direction and irradiance as attributes) or .png "
                "(tone-mapped preview)")
      ->required();
  AddPathOption(*command, "--cube-map", options->cube_map,
                "Also write a cube map (.exr, OpenEXR's cube layout, faces a quarter of --width)");
  command->add_option("--width", options->width, "Lat-long map width in pixels (twice the height)");
  command->add_option("--height", options->height, "Lat-long map height in pixels");
  command->add_option("--altitude-m", options->altitude_m, "Altitude of the point above the ground (m)");
  command->add_option("--sun-zenith-deg", options->sun_zenith_deg, "Sun zenith angle (deg; default 30)");
  command->add_option("--sun-azimuth-deg", options->sun_azimuth_deg, "Sun compass azimuth (deg; default 180)");
  options->sun_date.AddTo(*command);
  command->add_option("--sun-disc", options->sun_disc,
                      "The sun's disc: off (default: left out, its direction and irradiance written as attributes "
                      "for a sun lamp) or on (in the map)")
      ->check(CLI::IsMember({"on", "off"}));
  options->tables.AddTo(*command);
  command->callback([options] { RunEnvmap(*options); });
}

}  // namespace aerial::cli
