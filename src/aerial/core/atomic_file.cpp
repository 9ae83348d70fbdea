#include "aerial/core/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <system_error>

#include "aerial/core/file_kind.h"
#include "aerial/core/live_temporary.h"
#include "aerial/error.h"

namespace aerial {
namespace fs = std::filesystem;
namespace {

// One message shape for all I/O failures: the file, what we tried and why the OS refused.
[[noreturn]] void Fail(const fs::path& path, const std::string& action, int error_number) {
  throw Error("file", path.string(),
              "a path where we can " + action + " (" + std::strerror(error_number) + ")");
}

// Closes the descriptor on every exit path, including exceptions.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

fs::path ParentOf(const fs::path& path) {
  fs::path parent = path.parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

// Creates the parent directory when missing, and fails clearly when it is not a directory
// (e.g. a regular file sits where a directory component should be).
void EnsureParentDirectory(const fs::path& path) {
  fs::path parent = ParentOf(path);
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) Fail(path, "create the directory " + parent.string(), ec.value());
  if (!fs::is_directory(parent, ec))
    Fail(path, "use " + parent.string() + " as a directory", ENOTDIR);
}

// The pid separates concurrent processes (and tells RemoveStaleTemporaries whether the writer
// still runs); the random part separates threads and reused pids. The constants spell out the
// format below for TemporaryOwner.
constexpr std::string_view kTemporaryMarker = ".tmp-";
constexpr size_t kRandomDigits = 16;

fs::path TemporaryNameFor(const fs::path& path) {
  static thread_local std::mt19937_64 random{std::random_device{}()};
  char suffix[64];
  std::snprintf(suffix, sizeof suffix, ".tmp-%ld-%016llx", static_cast<long>(::getpid()),
                static_cast<unsigned long long>(random()));
  fs::path temporary = path;
  temporary += suffix;
  return temporary;
}

// The writer's pid when name is "<target>.tmp-<pid>-<16 lowercase hex digits>" with a target
// starting with target_prefix, else 0.
pid_t TemporaryOwner(std::string_view name, std::string_view target_prefix) {
  if (!name.starts_with(target_prefix)) return 0;
  size_t marker = name.rfind(kTemporaryMarker);
  if (marker == std::string_view::npos || marker == 0 || marker < target_prefix.size()) return 0;
  std::string_view rest = name.substr(marker + kTemporaryMarker.size());  // "<pid>-<hex>"
  size_t dash = rest.find('-');
  if (dash == std::string_view::npos || dash == 0 || rest.size() - dash - 1 != kRandomDigits) return 0;
  long pid = 0;
  for (char c : rest.substr(0, dash)) {
    if (c < '0' || c > '9' || pid > 1'000'000'000) return 0;
    pid = pid * 10 + (c - '0');
  }
  for (char c : rest.substr(dash + 1))
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return 0;
  return static_cast<pid_t>(pid);
}

// The file a write replaces: the target of a symbolic link (which is kept), else path itself.
fs::path ReplacedPath(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_symlink(path, ec)) return path;
  fs::path target = fs::canonical(path, ec);
  return ec ? path : target;
}

// Outputs are regular files, replaced whole. What sits at path (after symbolic links) is nothing,
// a regular file (returned, for its mode and owner) or something else, which is refused by name:
// renaming over a device, FIFO or socket would replace it (as root, `--stats /dev/null` would
// replace the system's /dev/null), and writing into one could not be atomic (a FIFO without a
// reader also blocks). field names the option in messages, which show the path as written and
// the file a link leads to.
std::optional<struct stat> ExistingRegularFile(const fs::path& path, const std::string& field) {
  struct stat info;
  if (::stat(path.c_str(), &info) != 0) {
    if (errno == ENOENT) return std::nullopt;  // nothing there (or a dangling link)
    Fail(path, "write a file", errno);          // a symbolic link loop, a search permission
  }
  if (S_ISREG(info.st_mode)) return info;
  fs::path target = ReplacedPath(path);
  throw Error(field, path.string(),
              std::string("a regular file or a new one, not ") + FileKindName(info.st_mode) +
                  (target == path ? "" : " (" + target.string() + ")") +
                  " (outputs are written whole to a temporary and renamed over the path)");
}

// The replacement keeps the replaced file's mode and, where the process may set it, its owner
// (root, or a file of ours): a non-root writer cannot give a file away, so its replacement of
// someone else's writable file is its own, as with any editor that saves by renaming. Hard links
// to the old file keep the old content: a rename replaces one name, and writing in place instead
// would let a crash or a full disk leave the file half written, which atomic outputs promise never
// to do.
void KeepModeAndOwner(int fd, const struct stat& existing, const fs::path& path) {
  if (::fchmod(fd, existing.st_mode & 07777) != 0) Fail(path, "keep the mode of", errno);
  if (::fchown(fd, existing.st_uid, existing.st_gid) != 0 && errno != EPERM)
    Fail(path, "keep the owner of", errno);
}

// Failures name the target, the path the user asked for; the temporary is removed by the caller.
void WriteAll(int fd, const std::byte* data, size_t size, const fs::path& path) {
  while (size > 0) {
    ssize_t written = ::write(fd, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      Fail(path, "write", errno);
    }
    data += written;
    size -= static_cast<size_t>(written);
  }
}

// Makes the rename itself durable. Some file systems cannot fsync a directory (EINVAL); there
// the rename is as durable as the file system allows and nothing is lost by skipping it.
void SyncDirectory(const fs::path& directory) {
  Fd dir{::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
  if (dir.fd < 0) Fail(directory, "open the directory to sync it", errno);
  if (::fsync(dir.fd) != 0 && errno != EINVAL) Fail(directory, "sync the directory", errno);
}

// Syncs and closes the written temporary, then renames it over path. close() can report a
// deferred write error (NFS, quota), so it is checked rather than left to the destructor.
void CommitTemporary(Fd& file, const fs::path& temporary, const fs::path& path) {
  if (::fsync(file.fd) != 0) Fail(path, "write (sync)", errno);
  int fd = file.fd;
  file.fd = -1;
  if (::close(fd) != 0) Fail(path, "write (close)", errno);
  if (::rename(temporary.c_str(), path.c_str()) != 0) Fail(path, "rename a file over", errno);
}

// What WriteFileAtomically(path) will replace is a regular file or nothing, and a file can be
// created beside it. Creating a file tests the very operation the write will do; access(W_OK)
// checks permission bits only and misses, e.g., NFS root squashing or a full inode table.
void CheckReplaceable(const fs::path& path, const std::string& field) {
  ExistingRegularFile(path, field);
  const fs::path target = ReplacedPath(path);
  const fs::path probe = TemporaryNameFor(target);
  Fd file{::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644)};
  if (file.fd < 0) Fail(path, "create a file in " + ParentOf(target).string(), errno);
  ::unlink(probe.c_str());
}

}  // namespace

void WriteFileAtomically(const fs::path& path, std::span<const std::byte> bytes) {
  EnsureParentDirectory(path);
  std::optional<struct stat> existing = ExistingRegularFile(path, "file");
  const fs::path target = ReplacedPath(path);
  RemoveStaleTemporaries(ParentOf(target), target.filename().string());
  const fs::path temporary = TemporaryNameFor(target);
  Fd file{::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644)};
  if (file.fd < 0) Fail(path, "create the temporary " + temporary.filename().string(), errno);
  LiveTemporary live(temporary);
  try {
    if (existing) KeepModeAndOwner(file.fd, *existing, path);
    WriteAll(file.fd, bytes.data(), bytes.size(), path);
    CommitTemporary(file, temporary, target);
  } catch (...) {
    ::unlink(temporary.c_str());
    throw;
  }
  SyncDirectory(ParentOf(target));
}

void WriteFileAtomically(const fs::path& path, std::string_view text) {
  WriteFileAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

std::vector<fs::path> RemoveStaleTemporaries(const fs::path& directory, std::string_view target_prefix) {
  std::vector<fs::path> removed;
  std::error_code ec;
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code ignored;
    pid_t owner = TemporaryOwner(it->path().filename().string(), target_prefix);
    if (owner <= 0 || !it->is_regular_file(ignored)) continue;
    if (::kill(owner, 0) == 0 || errno != ESRCH) continue;  // running, or not ours to signal
    if (fs::remove(it->path(), ignored)) removed.push_back(it->path());
  }
  return removed;
}

std::vector<std::byte> ReadFile(const fs::path& path) {
  Fd file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) Fail(path, "open a file for reading", errno);
  struct stat info;
  if (::fstat(file.fd, &info) != 0) Fail(path, "stat", errno);
  if (S_ISDIR(info.st_mode)) Fail(path, "read a file", EISDIR);
  std::vector<std::byte> bytes;
  bytes.reserve(static_cast<size_t>(info.st_size));
  // Read until end of file rather than trusting st_size: /proc files and pipes report 0.
  std::byte chunk[1 << 16];
  for (;;) {
    ssize_t got = ::read(file.fd, chunk, sizeof chunk);
    if (got < 0) {
      if (errno == EINTR) continue;
      Fail(path, "read", errno);
    }
    if (got == 0) break;
    bytes.insert(bytes.end(), chunk, chunk + got);
  }
  return bytes;
}

void CheckWritable(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) Fail(path, "write a file", EISDIR);
  EnsureParentDirectory(path);
  CheckReplaceable(path, "file");
}

void CheckOutputFile(const fs::path& path, const std::string& field) {
  if (path.empty()) throw Error(field, "", "a file path");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Error(field, path.string(), "a file, not a directory");
  // An output goes where the user points; a mistyped directory is an error, not created silently
  // (unlike the table cache's and bench's directories, which are theirs to create).
  fs::path parent = ParentOf(path);
  if (!fs::is_directory(parent, ec))
    throw Error(field, path.string(), "a file in an existing directory (" + parent.string() +
                                          " does not exist or is not a directory)");
  CheckReplaceable(path, field);
}

}  // namespace aerial
