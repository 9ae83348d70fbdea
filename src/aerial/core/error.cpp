#include "aerial/core/error.h"

namespace aerial {
namespace {
std::string Compose(const std::string& field, const std::string& value, const std::string& allowed,
                    const std::string& where) {
  std::string message = where.empty() ? "" : where + ": ";
  message += field + " = " + (value.empty() ? "(empty)" : value);
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
