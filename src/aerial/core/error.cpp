#include "aerial/error.h"

#include <cstdio>

namespace aerial {

std::string Shortened(std::string_view text) {
  if (text.size() <= kMaxShownBytes) return std::string(text);
  size_t cut = kMaxShownBytes;
  // Cut before a character, not inside a UTF-8 sequence (continuation bytes are 10xxxxxx).
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return std::string(text.substr(0, cut)) + "\u2026 (" + std::to_string(text.size()) + " bytes)";
}

namespace {

// The length of the valid UTF-8 sequence that starts text (1 to 4 bytes), or 0: RFC 3629, which
// also refuses overlong forms, surrogates and code points above U+10FFFF.
size_t Utf8SequenceLength(std::string_view text) {
  auto byte = [&](size_t i) { return static_cast<unsigned char>(text[i]); };
  auto continuation = [&](size_t i) { return i < text.size() && (byte(i) & 0xC0) == 0x80; };
  unsigned char lead = byte(0);
  if (lead < 0x80) return 1;
  size_t length = lead >= 0xC2 && lead <= 0xDF   ? 2
                  : lead >= 0xE0 && lead <= 0xEF ? 3
                  : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                 : 0;
  if (length == 0) return 0;
  for (size_t i = 1; i < length; ++i)
    if (!continuation(i)) return 0;
  if (lead == 0xE0 && byte(1) < 0xA0) return 0;   // overlong
  if (lead == 0xED && byte(1) >= 0xA0) return 0;  // a surrogate
  if (lead == 0xF0 && byte(1) < 0x90) return 0;   // overlong
  if (lead == 0xF4 && byte(1) >= 0x90) return 0;  // above U+10FFFF
  return length;
}

void AppendEscape(std::string& out, const char* format, unsigned value) {
  char escape[8];
  std::snprintf(escape, sizeof escape, format, value);
  out += escape;
}

}  // namespace

std::string Printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    size_t length = Utf8SequenceLength(text.substr(i));
    if (c < 0x20 || c == 0x7F || length == 0) {
      AppendEscape(out, "\\x%02x", c);
      ++i;
    } else if (c == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0) {  // U+0080 to U+009F
      AppendEscape(out, "\\u%04x", static_cast<unsigned char>(text[i + 1]));
      i += 2;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

namespace {
std::string Compose(const std::string& field, const std::string& value, const std::string& allowed,
                    const std::string& where) {
  std::string message = where.empty() ? "" : Printable(where) + ": ";
  message += Printable(field) + " = " + (value.empty() ? "(empty)" : Printable(Shortened(value)));
  if (!allowed.empty()) message += " is invalid; expected " + Printable(allowed);
  return message;
}
}  // namespace

Error::Error(std::string field, std::string value, std::string allowed, std::string where)
    : std::runtime_error(Compose(field, value, allowed, where)),
      field_(std::move(field)),
      value_(std::move(value)),
      allowed_(std::move(allowed)),
      where_(std::move(where)) {}

}  // namespace aerial
