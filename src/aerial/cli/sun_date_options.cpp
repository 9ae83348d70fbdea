#include "aerial/cli/sun_date_options.h"

#include "aerial/error.h"

namespace aerial::cli {

void SunDateOptions::AddTo(CLI::App& command) {
  const std::string group = "Sun from a date and a place (instead of --sun-zenith-deg, --sun-azimuth-deg)";
  command.add_option("--date", date, "Local date, YYYY-MM-DD (" + std::to_string(astronomy::kFirstYear) + " to " +
                                         std::to_string(astronomy::kLastYear) + ")")
      ->group(group);
  command.add_option("--time", time, "Local clock time, HH:MM[:SS]")->group(group);
  command.add_option("--time-zone", time_zone,
                     "Time zone of --date and --time: a tz database name (Europe/Paris, UTC) or a UTC offset "
                     "(+02:00, -07)")
      ->group(group);
  command.add_option("--latitude-deg", latitude_deg, "Latitude of the place (deg, north positive)")->group(group);
  command.add_option("--longitude-deg", longitude_deg, "Longitude of the place (deg, east positive)")->group(group);
}

std::optional<astronomy::SunDate> SunDateOptions::Make() const {
  const bool given[] = {!date.empty(), !time.empty(), !time_zone.empty(), latitude_deg.has_value(),
                        longitude_deg.has_value()};
  const char* names[] = {"--date", "--time", "--time-zone", "--latitude-deg", "--longitude-deg"};
  int count = 0;
  for (bool g : given) count += g;
  if (count == 0) return std::nullopt;
  for (int i = 0; i < 5; ++i) {
    if (!given[i])
      throw Error(names[i], "(not given)", "a value too: the sun from a date needs --date, --time, --time-zone, --latitude-deg "
                                "and --longitude-deg together");
  }
  return astronomy::SunDate{date, time, time_zone, *latitude_deg, *longitude_deg};
}

}  // namespace aerial::cli
