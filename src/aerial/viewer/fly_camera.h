#pragma once
// The fly camera: keys move the camera along its view direction, its horizontal right and the
// world's up; the mouse turns it. Pure state update, so it is tested without a window.
#include "aerial/scene.h"

namespace aerial::viewer {

struct FlyInput {
  double forward = 0;  // +1 W, -1 S
  double right = 0;    // +1 D, -1 A
  double up = 0;       // +1 E, -1 Q (world up, +z)
  bool fast = false;   // Shift: 10x
  bool slow = false;   // Ctrl: 1/10
  double look_dx_px = 0, look_dy_px = 0;  // pointer motion while turning (right button held)
};

struct FlySpeeds {
  double meters_per_second = 200.0;  // crosses the 1-40 km landmark corridor in seconds
  double degrees_per_pixel = 0.15;
};

// Moves and turns the camera for dt_s seconds of input. Pitch stays within [-89, 89] degrees, so
// the horizontal right vector stays defined; yaw wraps to [0, 360). The altitude stays within the
// scene files' camera range (scene_limits.h: -500 m to 100 km above the sphere of radius
// planet_radius_m).
void Fly(Camera& camera, const FlyInput& input, double dt_s, double planet_radius_m,
         const FlySpeeds& speeds = {});

}  // namespace aerial::viewer
