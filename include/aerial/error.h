#pragma once
// One error type for every boundary of the program (configs, CLI values, files, Vulkan results).
// It names what was wrong (field), the offending value and what was allowed, so a message is
// actionable on its own. It is thrown at the boundary and caught once, in main().
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace aerial {

// The longest value a message shows whole: any path one would type, but not a data URI.
inline constexpr size_t kMaxShownBytes = 200;

// text as a message shows it: whole up to kMaxShownBytes bytes, else its first kMaxShownBytes
// (less, not to split a UTF-8 character) and "… (N bytes)", so a value like a pasted data URI
// cannot flood the terminal.
std::string Shortened(std::string_view text);

// text as it may reach a terminal: every byte that a terminal could take as a command (the C0
// controls, NUL and ESC among them, and DEL) is written "\xNN", a C1 control (U+0080 to U+009F,
// which some terminals also obey) "\u00NN", and a byte that is not part of valid UTF-8 "\xNN";
// everything else is kept. Every message aerial prints passes through it (Error's what(), the
// command line's own messages), so a path, URI or name from a file cannot set a terminal's title
// or clear its screen, and a NUL cannot cut a message short.
std::string Printable(std::string_view text);

class Error : public std::runtime_error {
 public:
  // field: dotted name of the input ("rayleigh.scattering[1]", "RenderOptions::render_scale",
  // "cache header"): the library's errors name what its caller set, never an option of the aerial
  // command, which shows them under its own options.
  // value: the bad value as text (what() shows it Shortened; value() keeps it whole).
  // allowed: the accepted range or form. where: file or context.
  Error(std::string field, std::string value, std::string allowed, std::string where = "");

  const std::string& field() const { return field_; }
  const std::string& value() const { return value_; }
  const std::string& allowed() const { return allowed_; }
  const std::string& where() const { return where_; }

 private:
  std::string field_, value_, allowed_, where_;
};

}  // namespace aerial
