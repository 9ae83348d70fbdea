#pragma once
// The library's errors name what a program that embeds it sets ("RenderOptions::render_scale",
// "scene file"); the command's user set an option instead ("--render-scale", "--scene"). One table
// maps the one to the other, applied once where main() catches the library's Error, so that a
// message names what the user typed.
#include <string>

#include "aerial/error.h"

namespace aerial::cli {

// The option that sets an API field ("RenderOptions::render_scale" -> "--render-scale"), or the
// field unchanged when no option sets it.
std::string OptionName(const std::string& field);

// e with its field named by its option, and each qualified API field its expectation mentions
// ("a shorter FroxelGrid::far_m") too; the value and the rest of the text are kept.
Error WithOptionNames(const Error& e);

}  // namespace aerial::cli
