#include "aerial/core/format_number.h"

#include <charconv>

namespace aerial {

std::string FormatNumber(double value) {
  char buffer[64];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

}  // namespace aerial
