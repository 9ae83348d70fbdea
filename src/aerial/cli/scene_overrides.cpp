#include "aerial/cli/scene_overrides.h"

#include "aerial/cli/sun_date_options.h"
#include "aerial/error.h"
#include "aerial/scene/scene_limits.h"

namespace aerial::cli {

void ApplyOverrides(Scene& scene, const SceneOverrides& o, double planet_radius_m) {
  const std::string where = "command line";
  if (o.camera_position_m)
    CheckCameraPosition(*o.camera_position_m, planet_radius_m, "--camera-position-m", where);
  if (o.camera_yaw_deg) CheckAzimuthDeg(*o.camera_yaw_deg, "--camera-yaw-deg", where);
  if (o.camera_pitch_deg) CheckPitchDeg(*o.camera_pitch_deg, "--camera-pitch-deg", where);
  if (o.camera_fov_deg) CheckFovDeg(*o.camera_fov_deg, "--camera-fov-deg", where);
  if (o.sun_zenith_deg) CheckZenithDeg(*o.sun_zenith_deg, "--sun-zenith-deg", where);
  if (o.sun_azimuth_deg) CheckAzimuthDeg(*o.sun_azimuth_deg, "--sun-azimuth-deg", where);
  std::optional<Sun> dated;
  if (o.sun_date) {
    if (o.sun_zenith_deg || o.sun_azimuth_deg)
      throw Error("--date", o.sun_date->date, "no --sun-zenith-deg or --sun-azimuth-deg with it: the date, time and "
                  "place give the sun", where);
    dated = astronomy::SunFromDate(*o.sun_date, kSunDateOptions, where);
  }

  Camera& camera = scene.camera;
  camera.position = o.camera_position_m.value_or(camera.position);
  camera.yaw_deg = o.camera_yaw_deg.value_or(camera.yaw_deg);
  camera.pitch_deg = o.camera_pitch_deg.value_or(camera.pitch_deg);
  camera.vertical_fov_deg = o.camera_fov_deg.value_or(camera.vertical_fov_deg);
  scene.sun.zenith_deg = o.sun_zenith_deg.value_or(scene.sun.zenith_deg);
  scene.sun.azimuth_deg = o.sun_azimuth_deg.value_or(scene.sun.azimuth_deg);
  if (dated) scene.sun = *dated;
}

}  // namespace aerial::cli
