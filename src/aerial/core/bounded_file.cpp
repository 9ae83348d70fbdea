#include "aerial/core/bounded_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "aerial/core/file_kind.h"
#include "aerial/core/output_conflicts.h"
#include "aerial/error.h"

namespace aerial {
namespace {

[[noreturn]] void FailUnreadable(const std::filesystem::path& path, const std::string& field,
                                 int error_number) {
  throw Error(field, path.string(),
              std::string("a readable file (") + std::strerror(error_number) + ")");
}

void RequireRegular(const struct stat& info, const std::filesystem::path& path,
                    const std::string& field) {
  if (!S_ISREG(info.st_mode))
    throw Error(field, path.string(), std::string("a regular file, not ") + FileKindName(info.st_mode));
}

[[noreturn]] void FailTooBig(const std::filesystem::path& path, const std::string& field,
                             size_t max_bytes, const std::string& how, const std::string& note) {
  throw Error(
      field, path.string(),
      "a regular file of at most " + std::to_string(max_bytes) + " bytes (" + how + ")" + note);
}

// Closes the descriptor on every exit path, including exceptions.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::vector<unsigned char> ReadBoundedFile(const std::filesystem::path& path,
                                           const std::string& field, size_t max_bytes,
                                           const std::string& cap_note) {
  // A path from a file (a glTF URI, a scene's model) may hold a NUL, which the system would take
  // for its end: another file than the one named would be read.
  if (path.native().find('\0') != std::string::npos)
    throw Error(field, path.string(), "a path without a NUL character");
  // stat() first: opening a FIFO for reading blocks until a writer appears.
  struct stat info;
  if (::stat(path.c_str(), &info) != 0) FailUnreadable(path, field, errno);
  RequireRegular(info, path, field);
  if (static_cast<unsigned long long>(info.st_size) > max_bytes)
    FailTooBig(path, field, max_bytes, "it has " + std::to_string(info.st_size), cap_note);
  // The path may have been replaced since: O_NONBLOCK keeps a FIFO swapped in from blocking the
  // open, and fstat() checks what was opened.
  Fd file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY)};
  if (file.fd < 0) FailUnreadable(path, field, errno);
  if (::fstat(file.fd, &info) != 0) FailUnreadable(path, field, errno);
  RequireRegular(info, path, field);

  // Read until end of file, but at most one byte past the cap: st_size may be stale (a growing
  // file) or 0 (files under /proc).
  std::vector<unsigned char> bytes(std::min(static_cast<size_t>(info.st_size), max_bytes) + 1);
  size_t size = 0;
  for (;;) {
    if (size == bytes.size()) {
      if (size > max_bytes)
        FailTooBig(path, field, max_bytes, "it grew past that while read", cap_note);
      bytes.resize(std::min(2 * size, max_bytes + 1));
    }
    ssize_t got = ::read(file.fd, bytes.data() + size, bytes.size() - size);
    if (got < 0) {
      if (errno == EINTR) continue;
      FailUnreadable(path, field, errno);
    }
    if (got == 0) break;
    size += static_cast<size_t>(got);
  }
  bytes.resize(size);
  RecordInputFile(field, path, info);
  return bytes;
}

}  // namespace aerial
