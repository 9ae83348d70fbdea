#pragma once
// --date, --time, --time-zone, --latitude-deg and --longitude-deg: the sun from a local date,
// clock time and place (astronomy/sun_date.h) instead of --sun-zenith-deg and --sun-azimuth-deg,
// for every command that takes a sun (render, view, export-vdb, envmap).
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "aerial/astronomy/sun_date.h"

namespace aerial::cli {

// What messages call SunDate's fields on the command line.
inline const astronomy::SunDateFields kSunDateOptions{"--date", "--time", "--time-zone", "--latitude-deg",
                                                      "--longitude-deg"};

struct SunDateOptions {
  std::string date, time, time_zone;
  std::optional<double> latitude_deg, longitude_deg;

  void AddTo(CLI::App& command);
  // None when no option was given; all five, else Error naming the first one missing.
  std::optional<astronomy::SunDate> Make() const;
};

}  // namespace aerial::cli
