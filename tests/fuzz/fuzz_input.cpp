#include "fuzz_input.h"

#include <unistd.h>

#include <cstdio>
#include <stdexcept>

namespace aerial::fuzz {

std::filesystem::path WriteInputFile(const uint8_t* data, size_t size, std::string_view extension) {
  std::filesystem::path path = "/dev/shm/aerial-fuzz-" + std::to_string(getpid()) +
                               std::string(extension);
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file || std::fwrite(data, 1, size, file) != size || std::fclose(file) != 0) {
    throw std::runtime_error("fuzz harness: cannot write " + path.string());
  }
  return path;
}

}  // namespace aerial::fuzz
