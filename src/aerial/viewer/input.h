#pragma once
// Keys held and pointer motion of one frame, read from GLFW:
//   W/S forward/back, A/D left/right, Q/E down/up, Shift faster, Ctrl slower;
//   right button held + motion: look around;
//   arrow keys: sun azimuth (left/right) and elevation (up/down); left button drag: the same.
// Whatever the panel is using (pointer over it, a widget with the keyboard) is not read.
#include "aerial/viewer/fly_camera.h"

struct GLFWwindow;

namespace aerial::viewer {

struct FrameInput {
  FlyInput fly;
  double sun_d_azimuth_deg = 0, sun_d_zenith_deg = 0;
};

class InputReader {
 public:
  explicit InputReader(GLFWwindow* window);
  // dt_s: time since the last frame, for the keys that turn the sun at a fixed rate.
  FrameInput Read(double dt_s, bool panel_has_mouse, bool panel_has_keyboard);

 private:
  GLFWwindow* window_;
  double last_x_ = 0, last_y_ = 0;
};

}  // namespace aerial::viewer
