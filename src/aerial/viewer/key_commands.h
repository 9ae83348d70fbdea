#pragma once
// The viewer's one-press keys (held keys that fly the camera and turn the sun are input.h's):
//   F12, P  screenshot (screenshot.h)        V    froxels to VDB (froxel_export.h)
//   Tab     hide or show the panel           F1, ?  show or hide the keys' help
//   R       the camera back where it started Esc  quit
// Collected as GLFW key codes between two frames (Window::TakeKeyPresses); a key pressed twice
// in one frame toggles twice.
#include <vector>

namespace aerial::viewer {

struct KeyCommands {
  bool screenshot = false, export_vdb = false, reset_camera = false, quit = false;
  bool toggle_panel = false, toggle_help = false;
};

KeyCommands ReadKeyCommands(const std::vector<int>& keys);

// The lines of the help overlay: the keys above and input.h's, one "keys: what" each.
const std::vector<const char*>& KeyHelpLines();

}  // namespace aerial::viewer
