#include "aerial/vk/driver_manifests.h"

#include <sys/stat.h>

#include <cstdlib>
#include <sstream>

#include "aerial/core/file_kind.h"
#include "aerial/error.h"

namespace aerial::vk {
namespace {

// The variables the Vulkan loader reads, newest first.
constexpr const char* kVariables[] = {"VK_DRIVER_FILES", "VK_ICD_FILENAMES"};

}  // namespace

void CheckDriverManifests() {
  for (const char* variable : kVariables) {
    const char* value = std::getenv(variable);
    if (!value) continue;
    std::istringstream paths(value);
    for (std::string path; std::getline(paths, path, ':');) {
      struct stat info;
      if (path.empty() || ::stat(path.c_str(), &info) != 0) continue;  // the loader skips it
      if (!S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode)) {
        throw Error(variable, path,
                    std::string("the path of a Vulkan driver's JSON manifest (or a directory of them), "
                                "not ") + FileKindName(info.st_mode));
      }
    }
  }
}

void BlameDriverManifests(const std::string& loader_error) {
  for (const char* variable : kVariables) {
    if (const char* value = std::getenv(variable); value && *value) {
      throw Error(variable, value,
                  "Vulkan driver manifests (JSON) the Vulkan loader accepts; it answered " + loader_error +
                      " (a malformed manifest reads as host memory running out)");
    }
  }
}

}  // namespace aerial::vk
