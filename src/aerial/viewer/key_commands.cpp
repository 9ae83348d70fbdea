#include "aerial/viewer/key_commands.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace aerial::viewer {

KeyCommands ReadKeyCommands(const std::vector<int>& keys) {
  KeyCommands commands;
  for (int key : keys) {
    switch (key) {
      case GLFW_KEY_F12:
      case GLFW_KEY_P: commands.screenshot = true; break;
      case GLFW_KEY_V: commands.export_vdb = true; break;
      case GLFW_KEY_R: commands.reset_camera = true; break;
      case GLFW_KEY_ESCAPE: commands.quit = true; break;
      case GLFW_KEY_TAB: commands.toggle_panel = !commands.toggle_panel; break;
      // '?' is Shift and '/' on US layouts; GLFW names the key, not the character.
      case GLFW_KEY_F1:
      case GLFW_KEY_SLASH: commands.toggle_help = !commands.toggle_help; break;
      default: break;
    }
  }
  return commands;
}

const std::vector<const char*>& KeyHelpLines() {
  static const std::vector<const char*> lines = {
      "W A S D: fly forward, left, back, right",
      "Q E: down, up; Shift, Ctrl: faster, slower",
      "right-drag: look around",
      "arrow keys, left-drag: move the sun",
      "R: the camera back to its start",
      "Tab: hide or show the panel",
      "F12, P: screenshot (PNG and EXR)",
      "V: froxels to OpenVDB",
      "F1, ?: this help",
      "Esc: quit",
  };
  return lines;
}

}  // namespace aerial::viewer
