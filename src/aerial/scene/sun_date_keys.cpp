#include "aerial/scene/sun_date_keys.h"

#include <sstream>

#include "aerial/astronomy/sun_date.h"
#include "aerial/error.h"

namespace aerial {
namespace {

const astronomy::SunDateFields kFields{"sun.date", "sun.time", "sun.time_zone", "sun.latitude_deg",
                                       "sun.longitude_deg"};

// A TOML date or time as YYYY-MM-DD or HH:MM:SS, or a string to be parsed as one.
std::string DateOrTimeText(TomlReader& r, const toml::node& node, const std::string& field) {
  std::ostringstream text;
  if (const auto* date = node.as_date()) {
    text << date->get();
  } else if (const auto* time = node.as_time()) {
    text << time->get();
  } else {
    return r.String(node, field);
  }
  return text.str();
}

}  // namespace

void ReadSunDate(TomlReader& r, const toml::table& t, Sun& sun) {
  const char* keys[] = {"date", "time", "time_zone", "latitude_deg", "longitude_deg"};
  const toml::node* first = nullptr;
  for (const char* key : keys) first = first ? first : t.get(key);
  if (!first) return;
  for (const char* key : keys) {
    if (!t.get(key))
      throw Error(TomlReader::Join("sun", key), "(not given)",
                  "a value too: the sun from a date needs date, time, time_zone, latitude_deg and longitude_deg "
                  "together",
                  r.At(*first));
  }
  astronomy::SunDate date;
  date.date = DateOrTimeText(r, *t.get("date"), kFields.date);
  if (t.get("zenith_deg") || t.get("azimuth_deg"))
    throw Error(kFields.date, date.date,
                "no sun.zenith_deg or sun.azimuth_deg with it: the date, time and place give the sun",
                r.At(*t.get("date")));
  date.time = DateOrTimeText(r, *t.get("time"), kFields.time);
  date.time_zone = r.String(*t.get("time_zone"), kFields.time_zone);
  date.latitude_deg = r.Number(*t.get("latitude_deg"), kFields.latitude, "degrees");
  date.longitude_deg = r.Number(*t.get("longitude_deg"), kFields.longitude, "degrees");
  // Every field is named as the file spells it; the error points at the [sun] table's date.
  sun = astronomy::SunFromDate(date, kFields, r.At(*t.get("date")));
}

}  // namespace aerial
