#pragma once
// Camera paths for `aerial view --camera-path FILE`: keyframes of the camera's position and
// orientation, linearly interpolated, played at a fixed step per frame (kFrameStepS) so that a run
// sees the same views whatever its frame rate. TOML (examples/paths/*.toml):
//
//   [[keyframe]]                   # two or more, in increasing time_s
//   time_s = 0.0                   # >= 0, strictly increasing
//   position_m = [0.0, 0.0, 30.0]  # world frame of scene.h (x east, y north, z up), m
//   yaw_deg = 0.0                  # compass azimuth of the view, interpolated as written: go
//                                  # from 350 to 370, not to 10, to turn 20 degrees clockwise
//   pitch_deg = 4.0                # [-90, 90]
//   sun_zenith_deg = 60.0          # optional, in every keyframe or in none: the sun moves
//   sun_azimuth_deg = 250.0        # with the camera, interpolated the same way
//
// Every camera key of a keyframe is required; the sun's keys come as a pair. Errors name the key
// ("keyframe[2].position_m"), the value and the allowed range, at "file:line:column". What the
// path passes through between keyframes is checked too: a segment whose straight line runs below
// the altitudes a keyframe may have (through the planet) is refused naming both keyframes
// ("keyframe[1] to keyframe[2]"), its lowest point and when the camera would reach it. Before the
// first keyframe's time the camera
// holds it, after the last it holds the last.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aerial/scene.h"

namespace aerial::viewer {

// Path time advanced per frame: 30 frames per path second.
inline constexpr double kFrameStepS = 1.0 / 30.0;

struct CameraKeyframe {
  double time_s = 0;
  glm::dvec3 position_m{0.0};
  double yaw_deg = 0, pitch_deg = 0;
  std::optional<Sun> sun;  // the same in every keyframe: present in all or in none
};

class CameraPath {
 public:
  static CameraPath Load(const std::filesystem::path& path, double planet_radius_m);
  // where names the source in messages.
  static CameraPath Parse(std::string_view toml, const std::string& where, double planet_radius_m);

  // Sets position, yaw and pitch for path time t_s; the field of view and near plane stay.
  void Apply(double t_s, Camera& camera) const;
  // Whether the keyframes move the sun, and where it is at path time t_s.
  bool moves_sun() const { return keyframes_.front().sun.has_value(); }
  void ApplySun(double t_s, Sun& sun) const;
  double duration_s() const { return keyframes_.back().time_s; }
  const std::vector<CameraKeyframe>& keyframes() const { return keyframes_; }

 private:
  std::vector<CameraKeyframe> keyframes_;
};

}  // namespace aerial::viewer
