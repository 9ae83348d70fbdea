#pragma once
// Numbers in messages, shown as the user wrote them: the shortest text that reads back as the
// same double ("0.25", "6360000", "1e+308"), never rounded to six places as std::to_string does
// ("0.250000").
#include <string>

namespace aerial {

std::string FormatNumber(double value);

}  // namespace aerial
