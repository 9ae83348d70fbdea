#include "aerial/core/output_conflicts.h"

#include <mutex>
#include <optional>

#include "aerial/core/atomic_file.h"
#include "aerial/error.h"

namespace aerial {
namespace fs = std::filesystem;
namespace {

struct InputFile {
  std::string field;
  std::string path;
  dev_t device;
  ino_t inode;
};

std::mutex inputs_mutex;
std::vector<InputFile> inputs;

// A file as it is (device and inode), or, before it exists, where it will be written.
struct Identity {
  std::optional<std::pair<dev_t, ino_t>> file;
  std::string target;

  bool operator==(const Identity& other) const {
    return file ? file == other.file : !other.file && target == other.target;
  }
};

Identity Identify(const fs::path& path) {
  struct stat info;
  if (::stat(path.c_str(), &info) == 0) return {std::pair{info.st_dev, info.st_ino}, ""};
  std::error_code ec;
  fs::path target = fs::weakly_canonical(fs::absolute(OutputTarget(path), ec), ec);
  return {std::nullopt, (ec ? OutputTarget(path) : target).string()};
}

}  // namespace

void RecordInputFile(const std::string& field, const fs::path& path, const struct stat& info) {
  std::lock_guard lock(inputs_mutex);
  for (const InputFile& input : inputs)
    if (input.device == info.st_dev && input.inode == info.st_ino) return;  // once is enough
  inputs.push_back({field, path.string(), info.st_dev, info.st_ino});
}

void CheckOutputConflicts(const std::vector<NamedFile>& outputs) {
  std::vector<Identity> identities;
  for (size_t i = 0; i < outputs.size(); ++i) {
    const NamedFile& output = outputs[i];
    identities.push_back(output.path.empty() ? Identity{std::nullopt, ""} : Identify(output.path));
    if (output.path.empty()) continue;
    for (size_t j = 0; j < i; ++j) {
      if (outputs[j].path.empty() || !(identities[j] == identities[i])) continue;
      throw Error(output.field, output.path.string(),
                  "a file other than " + outputs[j].field + " " + outputs[j].path.string() +
                      " (two outputs of one command may not be the same file, directly or through a link)");
    }
    if (!identities[i].file) continue;
    std::lock_guard lock(inputs_mutex);
    for (const InputFile& input : inputs) {
      if (std::pair{input.device, input.inode} != *identities[i].file) continue;
      throw Error(output.field, output.path.string(),
                  "a file other than " + input.field + " " + input.path +
                      ", which this command reads (directly or through a link)");
    }
  }
}

}  // namespace aerial
