#include "aerial/viewer/input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace aerial::viewer {
namespace {

// Sun steering rates: a keypress of a second moves the sun visibly but not past the horizon.
constexpr double kSunAzimuthDegPerS = 45.0;
constexpr double kSunZenithDegPerS = 15.0;
constexpr double kSunDegPerPixel = 0.2;

}  // namespace

InputReader::InputReader(GLFWwindow* window) : window_(window) {
  glfwGetCursorPos(window_, &last_x_, &last_y_);
}

FrameInput InputReader::Read(double dt_s, bool panel_has_mouse, bool panel_has_keyboard) {
  FrameInput input;
  double x = 0, y = 0;
  glfwGetCursorPos(window_, &x, &y);
  double dx = x - last_x_, dy = y - last_y_;
  last_x_ = x;
  last_y_ = y;
  if (!panel_has_mouse) {
    if (glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) {
      input.fly.look_dx_px = dx;
      input.fly.look_dy_px = dy;
    } else if (glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) {
      input.sun_d_azimuth_deg = dx * kSunDegPerPixel;
      input.sun_d_zenith_deg = dy * kSunDegPerPixel;  // dragging down lowers the sun
    }
  }
  if (panel_has_keyboard) return input;
  auto held = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0 : 0.0; };
  input.fly.forward = held(GLFW_KEY_W) - held(GLFW_KEY_S);
  input.fly.right = held(GLFW_KEY_D) - held(GLFW_KEY_A);
  input.fly.up = held(GLFW_KEY_E) - held(GLFW_KEY_Q);
  input.fly.fast = held(GLFW_KEY_LEFT_SHIFT) + held(GLFW_KEY_RIGHT_SHIFT) > 0;
  input.fly.slow = held(GLFW_KEY_LEFT_CONTROL) + held(GLFW_KEY_RIGHT_CONTROL) > 0;
  input.sun_d_azimuth_deg += (held(GLFW_KEY_RIGHT) - held(GLFW_KEY_LEFT)) * kSunAzimuthDegPerS * dt_s;
  input.sun_d_zenith_deg += (held(GLFW_KEY_DOWN) - held(GLFW_KEY_UP)) * kSunZenithDegPerS * dt_s;
  return input;
}

}  // namespace aerial::viewer
