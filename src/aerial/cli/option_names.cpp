#include "aerial/cli/option_names.h"

#include <cctype>
#include <string_view>
#include <utility>
#include <vector>

namespace aerial::cli {
namespace {

// API field (as the library's errors name it) -> the option that sets it.
const std::vector<std::pair<std::string, std::string>> kOptionNames = {
    {"RenderOptions::width/height", "--width/--height"},
    {"RenderOptions::render_scale", "--render-scale"},
    {"RenderOptions::terrain_error_px", "--terrain-error-px"},
    {"FroxelGrid::width/height/depth", "--froxels"},
    {"FroxelGrid::far_m", "--froxel-far-m"},
    {"VdbExportOptions::world_grid_m", "--world-grid"},
    {"VDB path", "--out"},
    {"preset name", "--preset"},
    {"scene file", "--scene"},
    {"atmosphere file", "--atmosphere"},
    {"ViewAngles::altitude_m", "--altitude-m"},
    {"ViewAngles::view_zenith_deg", "--view-zenith-deg"},
    {"ViewAngles::sun_zenith_deg", "--sun-zenith-deg"},
    {"ViewAngles::azimuth_deg", "--azimuth-deg"},
    {"TableResolution::transmittance_mu/r", "transmittance size (--transmittance-size)"},
    {"TableResolution::irradiance_mu_s/r", "irradiance size (--irradiance-size)"},
    {"TableResolution::scattering_r/mu/mu_s/nu", "scattering size (--scattering-size)"},
    {"PrecomputeOptions::orders", "--orders"},
};

bool PartOfAName(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':'; }

// text with each qualified field ("Type::member") that stands as a whole name in it replaced by
// its option. Unqualified ones ("scene file") are left: as words they could be the text's own.
std::string WithQualifiedNamesReplaced(std::string text) {
  for (const auto& [field, option] : kOptionNames) {
    if (field.find("::") == std::string::npos) continue;
    for (size_t at = text.find(field); at != std::string::npos; at = text.find(field, at)) {
      const size_t end = at + field.size();
      if ((at > 0 && PartOfAName(text[at - 1])) || (end < text.size() && PartOfAName(text[end]))) {
        at = end;
        continue;
      }
      text.replace(at, field.size(), option);
      at += option.size();
    }
  }
  return text;
}

}  // namespace

std::string OptionName(const std::string& field) {
  for (const auto& [api_field, option] : kOptionNames)
    if (api_field == field) return option;
  return field;
}

Error WithOptionNames(const Error& e) {
  return Error(OptionName(e.field()), e.value(), WithQualifiedNamesReplaced(e.allowed()), e.where());
}

}  // namespace aerial::cli
