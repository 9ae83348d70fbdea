#include "aerial/bench/bruneton_2017.h"

#include "aerial/bench/pass_stats.h"

namespace aerial::bench {

bool IsBruneton2017Device(const std::string& device) { return device.find("llvmpipe") != std::string::npos; }

std::string Bruneton2017Step(const std::string& pass) {
  std::string kind = PassKind(pass);
  if (kind == "incident radiance") return "scattering density";
  if (kind == "accumulate") return "multiple scattering";
  if (kind == "sun band") return "single scattering";  // its sunlight, tabulated beforehand
  for (const auto& step : kBruneton2017Steps)
    if (kind == step.name) return kind;
  return "";
}

}  // namespace aerial::bench
