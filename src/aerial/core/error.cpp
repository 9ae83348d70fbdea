#include "aerial/error.h"

namespace aerial {

std::string Shortened(std::string_view text) {
  if (text.size() <= kMaxShownBytes) return std::string(text);
  size_t cut = kMaxShownBytes;
  // Cut before a character, not inside a UTF-8 sequence (continuation bytes are 10xxxxxx).
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return std::string(text.substr(0, cut)) + "\u2026 (" + std::to_string(text.size()) + " bytes)";
}

namespace {
std::string Compose(const std::string& field, const std::string& value, const std::string& allowed,
                    const std::string& where) {
  std::string message = where.empty() ? "" : where + ": ";
  message += field + " = " + (value.empty() ? "(empty)" : Shortened(value));
  if (!allowed.empty()) message += " is invalid; expected " + allowed;
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
