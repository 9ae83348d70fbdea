#pragma once
// A fresh directory for one test's files, removed with all it holds when the test ends.
#include <filesystem>
#include <string>

namespace aerial::testing {

class ScratchDirectory {
 public:
  // Under the test temporary directory; name tells tests apart, the process id runs.
  explicit ScratchDirectory(const std::string& name);
  ~ScratchDirectory();
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

}  // namespace aerial::testing
