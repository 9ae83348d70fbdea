#include "aerial/cli/option_values.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

namespace aerial::cli {
namespace {

// text as a whole read as a double by strtod, the reading CLI11's conversion makes ("nan", "inf"
// and "1e999" included); none when text is not a number.
std::optional<double> AsNumber(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

bool IsFloatingPoint(const CLI::Option& option) { return option.get_type_name().rfind("FLOAT", 0) == 0; }

}  // namespace

void RefuseNonFiniteNumbers(CLI::App& app) {
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
    for (CLI::Option* option : command->get_options([](CLI::Option* o) { return IsFloatingPoint(*o); })) {
      const std::string name = option->get_name();
      auto finite = [name](const std::string& value) -> std::string {
        std::optional<double> number = AsNumber(value);
        if (number && !std::isfinite(*number)) throw Error(name, value, "a finite number");
        return "";  // anything else is the option's own conversion and checks to judge
      };
      // No description: the option's help keeps its type name.
      option->check(CLI::Validator(finite, ""));
    }
  }
}

Error AsTyped(const Error& e, const CLI::App& app) {
  for (const CLI::App* command : app.get_subcommands()) {
    const CLI::Option* option = command->get_option_no_throw(e.field());
    if (!option || option->results().size() != 1) continue;
    const std::string& typed = option->results().front();
    std::optional<double> typed_number = AsNumber(typed), shown_number = AsNumber(e.value());
    if (typed == e.value() || !typed_number || !shown_number || *typed_number != *shown_number) return e;
    return Error(e.field(), typed, e.allowed(), e.where());
  }
  return e;
}

}  // namespace aerial::cli
