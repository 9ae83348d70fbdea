#include "aerial/cli/sun_date_options.h"

#include <utility>

#include "aerial/error.h"

namespace aerial::cli {

void SunDateOptions::AddTo(CLI::App& command) {
  const std::string group = "Sun from a date and a place (instead of --sun-zenith-deg, --sun-azimuth-deg)";
  command.add_option(kSunDateOptions.date, date, "Local date, YYYY-MM-DD (" + std::to_string(astronomy::kFirstYear) + " to " +
                                         std::to_string(astronomy::kLastYear) + ")")
      ->group(group);
  command.add_option(kSunDateOptions.time, time, "Local clock time, HH:MM[:SS]")->group(group);
  command.add_option(kSunDateOptions.time_zone, time_zone,
                     "Time zone of --date and --time: a tz database name (Europe/Paris, UTC) or a UTC offset "
                     "(+02:00, -07)")
      ->group(group);
  command.add_option(kSunDateOptions.latitude, latitude_deg, "Latitude of the place (deg, north positive)")->group(group);
  command.add_option(kSunDateOptions.longitude, longitude_deg, "Longitude of the place (deg, east positive)")->group(group);
}

std::optional<astronomy::SunDate> SunDateOptions::Make() const {
  const std::pair<bool, const std::string&> given[] = {{!date.empty(), kSunDateOptions.date},
                                                       {!time.empty(), kSunDateOptions.time},
                                                       {!time_zone.empty(), kSunDateOptions.time_zone},
                                                       {latitude_deg.has_value(), kSunDateOptions.latitude},
                                                       {longitude_deg.has_value(), kSunDateOptions.longitude}};
  int count = 0;
  for (const auto& [is_given, name] : given) count += is_given;
  if (count == 0) return std::nullopt;
  for (const auto& [is_given, name] : given) {
    if (!is_given)
      throw Error(name, "(not given)", "a value too: the sun from a date needs --date, --time, --time-zone, --latitude-deg "
                                "and --longitude-deg together");
  }
  return astronomy::SunDate{date, time, time_zone, *latitude_deg, *longitude_deg};
}

}  // namespace aerial::cli
