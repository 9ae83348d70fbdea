#include "aerial/vk/loader_files.h"

#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "aerial/core/bounded_file.h"
#include "aerial/core/file_kind.h"
#include "aerial/error.h"

namespace aerial::vk {
namespace {

namespace fs = std::filesystem;

// The variables the loader reads driver manifests from, newest first.
constexpr const char* kDriverVariables[] = {"VK_DRIVER_FILES", "VK_ICD_FILENAMES"};

// Every variable that lists manifests or directories of them (the Vulkan loader's
// docs/LoaderInterfaceArchitecture.md, "Table of Debug Environment Variables").
constexpr const char* kListVariables[] = {"VK_DRIVER_FILES",        "VK_ICD_FILENAMES",
                                          "VK_ADD_DRIVER_FILES",    "VK_LAYER_PATH",
                                          "VK_ADD_LAYER_PATH",      "VK_IMPLICIT_LAYER_PATH",
                                          "VK_ADD_IMPLICIT_LAYER_PATH"};

// The manifest directories under each search root (the loader's LoaderDriverInterface.md and
// LoaderLayerInterface.md, "Linux Manifest Search Paths").
constexpr const char* kManifestDirectories[] = {"vulkan/icd.d", "vulkan/implicit_layer.d",
                                                "vulkan/explicit_layer.d"};

// A manifest is a few hundred bytes; a larger one is read by the loader but not searched here for
// its library (it cannot hang the loader by its size).
constexpr size_t kMaxManifestBytes = size_t{1} << 20;

std::vector<std::string> SplitPaths(std::string_view list) {
  std::vector<std::string> paths;
  for (size_t start = 0; start <= list.size();) {
    size_t end = std::min(list.find(':', start), list.size());
    if (end > start) paths.emplace_back(list.substr(start, end - start));
    start = end + 1;
  }
  return paths;
}

std::string Environment(const char* variable) {
  const char* value = std::getenv(variable);
  return value ? value : "";
}

void AppendUtf8(std::string& out, uint32_t code_point) {
  if (code_point < 0x80) {
    out += char(code_point);
  } else if (code_point < 0x800) {
    out += char(0xC0 | code_point >> 6);
    out += char(0x80 | (code_point & 0x3F));
  } else if (code_point < 0x10000) {
    out += char(0xE0 | code_point >> 12);
    out += char(0x80 | (code_point >> 6 & 0x3F));
    out += char(0x80 | (code_point & 0x3F));
  } else {
    out += char(0xF0 | code_point >> 18);
    out += char(0x80 | (code_point >> 12 & 0x3F));
    out += char(0x80 | (code_point >> 6 & 0x3F));
    out += char(0x80 | (code_point & 0x3F));
  }
}

// The four hex digits at json[at], or -1.
long Hex4(std::string_view json, size_t at) {
  if (at + 4 > json.size()) return -1;
  long value = 0;
  for (char c : json.substr(at, 4)) {
    int digit = c >= '0' && c <= '9'   ? c - '0'
                : c >= 'a' && c <= 'f' ? c - 'a' + 10
                : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                       : -1;
    if (digit < 0) return -1;
    value = value * 16 + digit;
  }
  return value;
}

// The JSON string that opens at json[at] (a '"'), decoded by RFC 8259's escapes; end is set just
// past it (or to the end of json when it is not closed).
std::string JsonString(std::string_view json, size_t at, size_t& end) {
  std::string text;
  size_t i = at + 1;
  for (; i < json.size() && json[i] != '"'; ++i) {
    if (json[i] != '\\' || i + 1 >= json.size()) {
      text += json[i];
      continue;
    }
    char escaped = json[++i];
    switch (escaped) {
      case 'b': text += '\b'; break;
      case 'f': text += '\f'; break;
      case 'n': text += '\n'; break;
      case 'r': text += '\r'; break;
      case 't': text += '\t'; break;
      case 'u': {
        long unit = Hex4(json, i + 1);
        if (unit < 0) break;
        i += 4;
        bool high_surrogate = unit >= 0xD800 && unit < 0xDC00;
        long low = high_surrogate && json.substr(i + 1, 2) == "\\u" ? Hex4(json, i + 3) : -1;
        if (low >= 0xDC00 && low < 0xE000) {
          AppendUtf8(text, 0x10000 + ((uint32_t(unit) - 0xD800) << 10) + (uint32_t(low) - 0xDC00));
          i += 6;
        } else {
          AppendUtf8(text, uint32_t(unit));
        }
        break;
      }
      default: text += escaped;  // '"', '\\' and '/' stand for themselves
    }
  }
  end = std::min(i + 1, json.size());
  return text;
}

// The values of every "library_path" key in a manifest (a driver's "ICD" object, a layer's "layer"
// or each of its "layers"), found by reading every string of the JSON text: a key is a string
// followed by ':', so the words inside other strings are never taken for one.
std::vector<std::string> LibraryPaths(std::string_view json) {
  std::vector<std::string> paths;
  constexpr const char* kSpace = " \t\r\n";
  for (size_t i = json.find('"'); i < json.size(); i = json.find('"', i)) {
    size_t end = i;
    bool is_key = JsonString(json, i, end) == "library_path";
    i = end;
    size_t colon = json.find_first_not_of(kSpace, end);
    if (!is_key || colon == std::string_view::npos || json[colon] != ':') continue;
    size_t value = json.find_first_not_of(kSpace, colon + 1);
    if (value == std::string_view::npos || json[value] != '"') continue;
    paths.push_back(JsonString(json, value, i));
  }
  return paths;
}

// The kind of what is at path (following links), or none when nothing the loader could open is
// there (it skips a missing or unreadable path).
std::optional<mode_t> KindAt(const fs::path& path) {
  struct stat info;
  if (::stat(path.c_str(), &info) != 0) return std::nullopt;
  return info.st_mode;
}

// A manifest's libraries: each named by a path must be a regular file.
void CheckManifest(const std::string& field, const fs::path& manifest) {
  std::vector<unsigned char> bytes;
  try {
    bytes = ReadBoundedFile(manifest, field, kMaxManifestBytes);
  } catch (const Error&) {
    return;  // unreadable or oversized: the loader skips or reads it, without blocking
  }
  std::string_view json(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  for (const std::string& library : LibraryPaths(json)) {
    if (library.find('/') == std::string::npos) continue;  // found by the dynamic linker
    fs::path path = fs::path(library).is_absolute() ? fs::path(library) : manifest.parent_path() / library;
    std::optional<mode_t> kind = KindAt(path);
    if (kind && !S_ISREG(*kind)) {
      throw Error(field, manifest.string(),
                  "a Vulkan manifest whose library_path is a regular file, not " +
                      std::string(FileKindName(*kind)) + " (" + path.string() + ")");
    }
  }
}

// The *.json entries of a directory the loader searches: regular files (or links to them).
void CheckDirectory(const std::string& field, const fs::path& directory) {
  std::error_code ec;
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path entry = it->path();
    if (entry.extension() != ".json") continue;  // the loader reads only these
    std::optional<mode_t> kind = KindAt(entry);
    if (!kind) continue;
    if (!S_ISREG(*kind)) {
      throw Error(field, entry.string(),
                  "a directory of Vulkan manifests whose *.json entries are regular files, not " +
                      std::string(FileKindName(*kind)) + " (the loader reads each)");
    }
    CheckManifest(field, entry);
  }
}

// A path a variable lists: a manifest or a directory of them.
void CheckListedPath(const std::string& field, const fs::path& path) {
  std::optional<mode_t> kind = KindAt(path);
  if (!kind) return;
  if (S_ISDIR(*kind)) return CheckDirectory(field, path);
  if (!S_ISREG(*kind)) {
    throw Error(field, path.string(),
                std::string("the path of a Vulkan manifest (JSON) or a directory of them, not ") +
                    FileKindName(*kind));
  }
  CheckManifest(field, path);
}

// The loader's own search roots, each under the variable that sets it (or the fixed path).
std::vector<std::pair<std::string, fs::path>> SearchRoots() {
  const std::string home = Environment("HOME");
  auto one_or = [&](const char* variable, const std::string& fallback) {
    std::string value = Environment(variable);
    return value.empty() ? fallback : value;
  };
  std::vector<std::pair<std::string, fs::path>> roots;
  auto add = [&](const char* variable, const std::string& list) {
    for (const std::string& root : SplitPaths(list)) roots.emplace_back(variable, root);
  };
  if (!home.empty() || !Environment("XDG_CONFIG_HOME").empty())
    add("XDG_CONFIG_HOME", one_or("XDG_CONFIG_HOME", home + "/.config"));
  add("XDG_CONFIG_DIRS", one_or("XDG_CONFIG_DIRS", "/etc/xdg"));
  roots.emplace_back("Vulkan loader search path", "/etc");
  if (!home.empty() || !Environment("XDG_DATA_HOME").empty())
    add("XDG_DATA_HOME", one_or("XDG_DATA_HOME", home + "/.local/share"));
  add("XDG_DATA_DIRS", one_or("XDG_DATA_DIRS", "/usr/local/share:/usr/share"));
  return roots;
}

}  // namespace

void CheckLoaderFiles() {
  for (const char* variable : kListVariables)
    for (const std::string& path : SplitPaths(Environment(variable))) CheckListedPath(variable, path);
  for (const auto& [field, root] : SearchRoots()) {
    for (const char* directory : kManifestDirectories) {
      std::optional<mode_t> kind = KindAt(root / directory);
      if (kind && S_ISDIR(*kind)) CheckDirectory(field, root / directory);
    }
  }
}

void BlameDriverManifests(const std::string& loader_error) {
  for (const char* variable : kDriverVariables) {
    if (const char* value = std::getenv(variable); value && *value) {
      throw Error(variable, value,
                  "Vulkan driver manifests (JSON) the Vulkan loader accepts; it answered " + loader_error +
                      " (a malformed manifest reads as host memory running out)");
    }
  }
}

}  // namespace aerial::vk
