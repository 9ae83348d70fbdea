#include "aerial/validation/reference_file.h"

#include <string>
#include <vector>

#include "aerial/core/atomic_file.h"
#include "aerial/error.h"

namespace aerial::validation {

nlohmann::json ReadReferenceJson(const std::filesystem::path& path, int version) {
  const std::vector<std::byte> bytes = ReadFile(path);
  nlohmann::json j = nlohmann::json::parse(reinterpret_cast<const char*>(bytes.data()),
                                           reinterpret_cast<const char*>(bytes.data()) + bytes.size());
  if (j.at("version").get<int>() != version)
    throw Error("version", j.at("version").dump(), std::to_string(version), path.string());
  return j;
}

}  // namespace aerial::validation
