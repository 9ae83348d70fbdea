#include "scratch_directory.h"

#include <gtest/gtest.h>
#include <unistd.h>

namespace aerial::testing {

ScratchDirectory::ScratchDirectory(const std::string& name)
    : path_(std::filesystem::path(::testing::TempDir()) /
            ("aerial_" + name + "_" + std::to_string(::getpid()))) {
  std::filesystem::create_directories(path_);
}

ScratchDirectory::~ScratchDirectory() {
  std::error_code ignored;  // a destructor must not throw
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace aerial::testing
