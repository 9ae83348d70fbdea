#include "aerial/viewer/key_commands.h"

#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace aerial::viewer {
namespace {

TEST(KeyCommands, EachKeyAsksForItsCommand) {
  EXPECT_TRUE(ReadKeyCommands({GLFW_KEY_F12}).screenshot);
  EXPECT_TRUE(ReadKeyCommands({GLFW_KEY_P}).screenshot);
  EXPECT_TRUE(ReadKeyCommands({GLFW_KEY_V}).export_vdb);
  EXPECT_TRUE(ReadKeyCommands({GLFW_KEY_R}).reset_camera);
  EXPECT_TRUE(ReadKeyCommands({GLFW_KEY_ESCAPE}).quit);
  EXPECT_TRUE(ReadKeyCommands({GLFW_KEY_TAB}).toggle_panel);
  EXPECT_TRUE(ReadKeyCommands({GLFW_KEY_F1}).toggle_help);
  EXPECT_TRUE(ReadKeyCommands({GLFW_KEY_SLASH}).toggle_help);
}

// The flying keys are held, not pressed: they ask for nothing here.
TEST(KeyCommands, OtherKeysAskForNothing) {
  KeyCommands none = ReadKeyCommands({GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_LEFT_SHIFT, GLFW_KEY_UP, GLFW_KEY_F2});
  EXPECT_FALSE(none.screenshot || none.export_vdb || none.reset_camera || none.quit || none.toggle_panel ||
               none.toggle_help);
}

// Two presses of Tab within one frame show the panel again: each press toggles.
TEST(KeyCommands, TwoPressesInOneFrameCancel) {
  EXPECT_FALSE(ReadKeyCommands({GLFW_KEY_TAB, GLFW_KEY_TAB}).toggle_panel);
  EXPECT_FALSE(ReadKeyCommands({GLFW_KEY_F1, GLFW_KEY_SLASH}).toggle_help);
  EXPECT_TRUE(ReadKeyCommands({GLFW_KEY_TAB, GLFW_KEY_TAB, GLFW_KEY_TAB}).toggle_panel);
}

}  // namespace
}  // namespace aerial::viewer
