#pragma once
// Command-line changes to a scene's camera and sun, applied after the preset or scene file.
#include <glm/glm.hpp>
#include <optional>

#include "aerial/astronomy/sun_date.h"
#include "aerial/scene.h"

namespace aerial::cli {

// Each set value replaces the scene's. Error messages name the values by their options.
struct SceneOverrides {
  std::optional<glm::dvec3> camera_position_m;  // --camera-position-m
  std::optional<double> camera_yaw_deg;         // --camera-yaw-deg
  std::optional<double> camera_pitch_deg;       // --camera-pitch-deg
  std::optional<double> camera_fov_deg;         // --camera-fov-deg
  std::optional<double> sun_zenith_deg;         // --sun-zenith-deg
  std::optional<double> sun_azimuth_deg;        // --sun-azimuth-deg
  // The sun from a date and a place (--date, --time, --time-zone, --latitude-deg,
  // --longitude-deg): instead of the two angles, never with them.
  std::optional<astronomy::SunDate> sun_date;
};

// Validates every set value with the scene file's ranges (scene_limits.h) and then applies them;
// nothing is applied if any is invalid. The position check needs the planet radius (camera
// altitude is measured above the sphere). Errors have where = "command line".
void ApplyOverrides(Scene& scene, const SceneOverrides& overrides, double planet_radius_m);

}  // namespace aerial::cli
