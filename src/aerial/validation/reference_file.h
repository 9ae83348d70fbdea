#pragma once
// The JSON files in which the accuracy tools keep their CPU references (sky_accuracy.h,
// colour_accuracy.h): read whole, and refused when another version of the tool wrote them.
#include <filesystem>
#include <nlohmann/json.hpp>

namespace aerial::validation {

// The file's JSON, whose "version" is `version`. Throws aerial::Error naming the file where it
// cannot be read or is of another version, and nlohmann::json's exceptions where it is not JSON.
nlohmann::json ReadReferenceJson(const std::filesystem::path& path, int version);

}  // namespace aerial::validation
