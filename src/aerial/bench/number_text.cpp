#include "aerial/bench/number_text.h"

#include <cstdio>

namespace aerial::bench {

std::string Format(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string Format(const char* format, std::optional<double> v) { return v ? Format(format, *v) : "—"; }

std::string Percent(double fraction) { return Format(fraction < 0.1 ? "%.2f%%" : "%.1f%%", 100.0 * fraction); }

}  // namespace aerial::bench
