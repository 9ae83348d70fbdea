#pragma once
// A scene file's sun from a date and a place: the [sun] keys date (a TOML date, 2003-10-17, or
// the same as a string), time (12:30:30, or a string), time_zone ("Europe/Paris", "-07:00"),
// latitude_deg and longitude_deg, all five together and instead of zenith_deg and azimuth_deg
// (astronomy/sun_date.h).
#include <toml++/toml.h>

#include "aerial/core/toml_reader.h"
#include "aerial/scene.h"

namespace aerial {

// Reads the five keys of the [sun] table `sun_table` if any of them is there, and sets `sun`
// from them. Throws aerial::Error naming the key ("sun.time_zone") for a missing or bad one, and
// naming sun.date when zenith_deg or azimuth_deg is there too.
void ReadSunDate(TomlReader& r, const toml::table& sun_table, Sun& sun);

}  // namespace aerial
