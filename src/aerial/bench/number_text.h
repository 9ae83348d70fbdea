#pragma once
// Numbers as the bench's reports print them.
#include <optional>
#include <string>

namespace aerial::bench {

// printf-style formatting of one number: Format("%.1f", 2.345) is "2.3".
std::string Format(const char* format, double v);
// The same, or "—" for a figure that was not measured.
std::string Format(const char* format, std::optional<double> v);
// A fraction as a percentage, two decimals below 10% and one above: "0.41%", "23.1%".
std::string Percent(double fraction);

}  // namespace aerial::bench
