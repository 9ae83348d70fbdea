#include "aerial/scene.h"

#include <cmath>
#include <numbers>

#include "aerial/error.h"
#include "aerial/scene/terrain.h"

namespace aerial {
namespace {

// Eye height above the valley floor: a low tower, high enough that the foreground terrain does
// not fill the lower half of the image.
constexpr double kEyeHeightM = 30.0;
constexpr double kHighAltitudeM = 30e3;

void CheckName(const std::string& name) {
  std::vector<std::string> names = PresetNames();
  for (const std::string& known : names)
    if (known == name) return;
  std::string allowed = "one of:";
  for (size_t i = 0; i < names.size(); ++i) allowed += (i ? ", " : " ") + names[i];
  throw Error("preset name", name, allowed);
}

}  // namespace

std::vector<std::string> PresetNames() {
  return {"noon", "afternoon", "sunset", "twilight", "high-altitude", "evening", "sunrise"};
}

void ApplyPresetView(Scene& scene, const std::string& name, double planet_radius_m) {
  CheckName(name);
  Camera camera;
  camera.position = {0.0, 0.0, TerrainHeightM(0.0, 0.0) + kEyeHeightM};
  camera.yaw_deg = 0.0;
  camera.pitch_deg = 4.0;
  camera.vertical_fov_deg = 50.0;
  camera.near_m = 0.5;
  Sun sun{20.0, 160.0};
  if (name == "afternoon") {
    sun = {55.0, 235.0};
  } else if (name == "sunset") {
    // Up the valley toward a sun 0.8 degrees up, its disc just behind the far end's hills: its
    // glow, the orange band of the reddened light either side of it, the mountains as
    // silhouettes. Raised and a little narrower than the default, so that the sky fills most of
    // the frame.
    sun = {89.2, 355.0};
    camera.pitch_deg = 10.0;
    camera.vertical_fov_deg = 40.0;
  } else if (name == "twilight") {
    // Away from a sun 2 degrees down, over the valley's low eastern side: the Earth's shadow, blue
    // grey on the horizon, and the belt of Venus, pink above it, which only the 4D tables show
    // (the 3D tables drop the view's azimuth from the sun).
    sun = {92.0, 270.0};
    camera.yaw_deg = 80.0;
    camera.pitch_deg = 6.0;
    camera.vertical_fov_deg = 35.0;
  } else if (name == "evening") {
    sun = {79.0, 300.0};
  } else if (name == "sunrise") {
    // Toward a sun 8 degrees up, just above the valley's far ridge: its disc, its aureole (the
    // Mie forward peak) and the near mountain's shadow in the air to its left.
    sun = {82.0, 200.0};
    camera.yaw_deg = 203.0;
    camera.pitch_deg = 5.0;
  } else if (name == "high-altitude") {
    sun = {50.0, 160.0};
    camera.position = {0.0, 0.0, kHighAltitudeM};
    // The horizon seen from altitude h lies acos(R / (R + h)) below the horizontal.
    double dip = std::acos(planet_radius_m / (planet_radius_m + kHighAltitudeM));
    camera.pitch_deg = -dip * 180.0 / std::numbers::pi;
    // 1 m is still far below the nearest geometry, 30 km away.
    camera.near_m = 1.0;
  }
  scene.camera = camera;
  scene.sun = sun;
  scene.name = name;
}

Scene BuildPreset(const std::string& name, double planet_radius_m) {
  CheckName(name);  // before building the scene
  Scene scene = BuildDefaultScene(planet_radius_m);
  ApplyPresetView(scene, name, planet_radius_m);
  return scene;
}

}  // namespace aerial
