#include "aerial/core/atomic_file.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "aerial/core/file_kind.h"
#include "aerial/core/live_temporary.h"
#include "aerial/error.h"

namespace aerial {
namespace fs = std::filesystem;
namespace {

// One message shape for all I/O failures: the file, what we tried and why the OS refused.
[[noreturn]] void Fail(const fs::path& path, const std::string& action, int error_number) {
  std::string reason = std::strerror(error_number);
  if (error_number == EFBIG)
    reason += ": the file would pass the file size limit (ulimit -f) or the file system's largest file";
  throw Error("file", path.string(), "a path where we can " + action + " (" + reason + ")");
}

// Closes the descriptor on every exit path, including exceptions.
struct Fd {
  int fd = -1;
  Fd() = default;
  explicit Fd(int descriptor) : fd(descriptor) {}
  Fd(Fd&& other) noexcept : fd(std::exchange(other.fd, -1)) {}
  Fd& operator=(Fd&&) = delete;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

fs::path ParentOf(const fs::path& path) {
  fs::path parent = path.parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

Fd OpenDirectory(const fs::path& directory, const fs::path& path) {
  Fd dir(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (dir.fd < 0) Fail(path, "use " + directory.string() + " as a directory", errno);
  return dir;
}

// A temporary is "<target name>.tmp-<pid>-<16 hex digits>", the target's name cut short (before a
// UTF-8 character) when the whole would pass the directory's longest name, so that any name a
// file may have can be written. The pid and the random digits separate concurrent writers (and
// tell a person whose file it is); whether its writer still runs is the lock's to say
// (CreateLockedTemporary), never the pid's, which another pid namespace or host reuses.
constexpr std::string_view kTemporaryMarker = ".tmp-";
constexpr size_t kRandomDigits = 16;
constexpr size_t kMaxSuffixBytes = 40;  // ".tmp-", a pid of up to 10 digits, "-", 16 digits, and room

size_t MaxNameBytes(int directory_fd) {
  long bytes = ::fpathconf(directory_fd, _PC_NAME_MAX);
  return bytes > long(kMaxSuffixBytes) ? size_t(bytes) : 255;
}

std::string TemporaryName(std::string_view target_name, size_t max_name_bytes) {
  static thread_local std::mt19937_64 random{std::random_device{}()};
  char suffix[kMaxSuffixBytes];
  int suffix_bytes = std::snprintf(suffix, sizeof suffix, ".tmp-%ld-%016llx", static_cast<long>(::getpid()),
                                   static_cast<unsigned long long>(random()));
  size_t keep = std::min(target_name.size(), max_name_bytes - size_t(suffix_bytes));
  auto continuation = [&](size_t i) { return (static_cast<unsigned char>(target_name[i]) & 0xC0) == 0x80; };
  while (keep > 0 && keep < target_name.size() && continuation(keep)) --keep;
  return std::string(target_name.substr(0, keep)) + suffix;
}

// The target name part of a temporary's name, when name has TemporaryName's form.
std::optional<std::string_view> TemporaryBase(std::string_view name) {
  size_t marker = name.rfind(kTemporaryMarker);
  if (marker == std::string_view::npos) return std::nullopt;
  std::string_view rest = name.substr(marker + kTemporaryMarker.size());  // "<pid>-<hex>"
  size_t dash = rest.find('-');
  if (dash == std::string_view::npos || dash == 0 || rest.size() - dash - 1 != kRandomDigits) return std::nullopt;
  for (char c : rest.substr(0, dash))
    if (c < '0' || c > '9') return std::nullopt;
  for (char c : rest.substr(dash + 1))
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return std::nullopt;
  return name.substr(0, marker);
}

// Whether name, in the directory, is still the file open as fd (a sweeper may have removed it).
bool StillNamed(int directory_fd, const std::string& name, int fd) {
  struct stat named, open;
  return ::fstatat(directory_fd, name.c_str(), &named, AT_SYMLINK_NOFOLLOW) == 0 &&
         ::fstat(fd, &open) == 0 && named.st_dev == open.st_dev && named.st_ino == open.st_ino;
}

// An exclusive flock on fd, waited for; true also where the file system has no locks (then no
// sweeper can take one either, and none removes the file).
bool Lock(int fd) {
  while (::flock(fd, LOCK_EX) != 0) {
    if (errno != EINTR) return errno == ENOLCK || errno == EOPNOTSUPP || errno == EINVAL;
  }
  return true;
}

struct Temporary {
  Fd file;
  std::string name;
};

// A new temporary for target_name in the directory, holding an exclusive flock for as long as it
// is open: the lock, released by the kernel however the writer ends, is what tells a sweeper that
// the writer is gone, in this pid namespace or another, on this host or another sharing the
// directory. A sweeper may take the lock between the file's creation and this writer's: the
// writer then finds its name gone and makes another.
Temporary CreateLockedTemporary(int directory_fd, const std::string& target_name, const fs::path& path) {
  const size_t max_name_bytes = MaxNameBytes(directory_fd);
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name = TemporaryName(target_name, max_name_bytes);
    Fd file(::openat(directory_fd, name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644));
    if (file.fd < 0) {
      if (errno == EEXIST) continue;
      Fail(path, "create the temporary " + name + " in " + ParentOf(path).string(), errno);
    }
    if (!Lock(file.fd)) {
      int error_number = errno;
      ::unlinkat(directory_fd, name.c_str(), 0);
      Fail(path, "lock the temporary " + name, error_number);
    }
    if (StillNamed(directory_fd, name, file.fd)) return {std::move(file), name};
  }
  Fail(path, "create a temporary", EEXIST);
}

// The temporaries in the directory that no live writer holds, whose target name starts with
// target_prefix (or, cut short, begins target_prefix), removed; their paths returned.
std::vector<fs::path> RemoveStale(int directory_fd, const fs::path& directory,
                                  std::string_view target_prefix) {
  std::vector<fs::path> removed;
  const size_t max_name_bytes = MaxNameBytes(directory_fd);
  std::error_code ec;
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    std::optional<std::string_view> base = TemporaryBase(name);
    if (!base || base->empty()) continue;
    bool cut = name.size() + 3 >= max_name_bytes;  // up to 3 bytes short, before a UTF-8 character
    if (!base->starts_with(target_prefix) && !(cut && target_prefix.starts_with(*base))) continue;
    // Opened without following a link or waiting on a FIFO: only regular files are temporaries.
    Fd file(::openat(directory_fd, name.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC));
    struct stat info;
    if (file.fd < 0 || ::fstat(file.fd, &info) != 0 || !S_ISREG(info.st_mode)) continue;
    // Held by a live writer, or a file system without locks: not provably stale, so kept.
    if (::flock(file.fd, LOCK_EX | LOCK_NB) != 0) continue;
    if (StillNamed(directory_fd, name, file.fd) && ::unlinkat(directory_fd, name.c_str(), 0) == 0)
      removed.push_back(directory / name);
  }
  return removed;
}

// The nearest directory at or above `directory` that exists; the directories below it that a
// write to path must make are added to missing, deepest first. Something other than a directory
// in the chain fails, naming it.
fs::path NearestDirectory(const fs::path& directory, const fs::path& path, std::vector<fs::path>& missing) {
  for (fs::path d = directory;; d = ParentOf(d)) {
    struct stat info;
    if (::stat(d.c_str(), &info) == 0) {
      if (!S_ISDIR(info.st_mode)) Fail(path, "use " + d.string() + " as a directory", ENOTDIR);
      return d;
    }
    if (errno != ENOENT || ParentOf(d) == d) Fail(path, "use " + d.string() + " as a directory", errno);
    missing.push_back(d);
  }
}

// The directories a write makes for its output (the missing part of the chain), registered with
// LiveTemporary until the write is done, so that a signal mid-write removes them again, as does a
// write that fails (they are empty then); a write that succeeds keeps them.
class MadeDirectories {
 public:
  MadeDirectories() = default;
  MadeDirectories(const MadeDirectories&) = delete;
  MadeDirectories& operator=(const MadeDirectories&) = delete;
  ~MadeDirectories() {
    if (kept_) return;
    for (size_t i = names_.size(); i-- > 0;) ::unlinkat(parents_[i].fd, names_[i].c_str(), AT_REMOVEDIR);
  }
  void Keep() { kept_ = true; }

  void Make(const fs::path& directory, const fs::path& path) {
    std::vector<fs::path> missing;
    NearestDirectory(directory, path, missing);
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
      Fd parent = OpenDirectory(ParentOf(*it), path);
      const std::string name = it->filename().string();
      if (::mkdirat(parent.fd, name.c_str(), 0777) != 0) {
        if (errno == EEXIST && fs::is_directory(*it)) continue;  // made by another process meanwhile
        Fail(path, "create the directory " + it->string(), errno);
      }
      live_.push_back(std::make_unique<LiveTemporary>(parent.fd, name, true));
      parents_.push_back(std::move(parent));
      names_.push_back(name);
    }
  }

 private:
  std::vector<Fd> parents_;  // open while registered
  std::vector<std::string> names_;
  std::vector<std::unique_ptr<LiveTemporary>> live_;
  bool kept_ = false;
};

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
  fs::path target = OutputTarget(path);
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
void SyncDirectory(int directory_fd, const fs::path& directory) {
  if (::fsync(directory_fd) != 0 && errno != EINVAL) Fail(directory, "sync the directory", errno);
}

// Syncs and closes the written temporary, then renames it over target_name. close() can report a
// deferred write error (NFS, quota), so it is checked rather than left to the destructor; a
// duplicate of the descriptor keeps the lock (which belongs to the open file) until the rename is
// done, so that no sweeper takes the finished temporary for a stale one.
void CommitTemporary(Temporary& temporary, int directory_fd, const std::string& target_name,
                     const fs::path& path) {
  if (::fsync(temporary.file.fd) != 0) Fail(path, "write (sync)", errno);
  Fd lock(::dup(temporary.file.fd));
  if (lock.fd < 0) Fail(path, "write (dup)", errno);
  int fd = std::exchange(temporary.file.fd, -1);
  if (::close(fd) != 0) Fail(path, "write (close)", errno);
  if (::renameat(directory_fd, temporary.name.c_str(), directory_fd, target_name.c_str()) != 0)
    Fail(path, "rename a file over", errno);
}

// A file can be created in the directory: creating one tests the very operation a write will do
// (access(W_OK) checks permission bits only and misses, e.g., NFS root squashing or a full inode
// table). The probe is removed at once.
void ProbeDirectory(const fs::path& directory, const std::string& target_name, const fs::path& path) {
  Fd dir = OpenDirectory(directory, path);
  Temporary probe = CreateLockedTemporary(dir.fd, target_name, path);
  LiveTemporary live(dir.fd, probe.name);
  ::unlinkat(dir.fd, probe.name.c_str(), 0);
}

// What WriteFileAtomically(path) will replace is a regular file or nothing, and a file can be
// created beside it.
void CheckReplaceable(const fs::path& path, const std::string& field) {
  ExistingRegularFile(path, field);
  const fs::path target = OutputTarget(path);
  ProbeDirectory(ParentOf(target), target.filename().string(), path);
}

}  // namespace

fs::path OutputTarget(const fs::path& path) {
  fs::path target = path;
  for (int links = 0;; ++links) {
    struct stat info;
    if (::lstat(target.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return target;
    if (links == 40) Fail(path, "write a file", ELOOP);  // the kernel's own limit
    std::error_code ec;
    fs::path link = fs::read_symlink(target, ec);
    if (ec) Fail(path, "read the symbolic link " + target.string(), ec.value());
    target = link.is_absolute() ? link : ParentOf(target) / link;
  }
}

void WriteFileAtomically(const fs::path& path, std::span<const std::byte> bytes) {
  const fs::path target = OutputTarget(path);
  std::optional<struct stat> existing = ExistingRegularFile(path, "file");
  MadeDirectories made;
  made.Make(ParentOf(target), path);
  Fd dir = OpenDirectory(ParentOf(target), path);
  const std::string name = target.filename().string();
  RemoveStale(dir.fd, ParentOf(target), name);
  Temporary temporary = CreateLockedTemporary(dir.fd, name, path);
  LiveTemporary live(dir.fd, temporary.name);
  try {
    if (existing) KeepModeAndOwner(temporary.file.fd, *existing, path);
    WriteAll(temporary.file.fd, bytes.data(), bytes.size(), path);
    CommitTemporary(temporary, dir.fd, name, path);
  } catch (...) {
    ::unlinkat(dir.fd, temporary.name.c_str(), 0);
    throw;
  }
  made.Keep();
  SyncDirectory(dir.fd, ParentOf(target));
}

void WriteFileAtomically(const fs::path& path, std::string_view text) {
  WriteFileAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

std::vector<fs::path> RemoveStaleTemporaries(const fs::path& directory, std::string_view target_prefix) {
  Fd dir(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (dir.fd < 0) return {};
  return RemoveStale(dir.fd, directory, target_prefix);
}

std::vector<std::byte> ReadFile(const fs::path& path) {
  Fd file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
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
  ExistingRegularFile(path, "file");
  const fs::path target = OutputTarget(path);
  // Nothing is made yet: the write makes the missing directories, in the nearest one that exists,
  // where the probe goes under the name the first of them will have.
  std::vector<fs::path> missing;
  fs::path directory = NearestDirectory(ParentOf(target), path, missing);
  ProbeDirectory(directory, (missing.empty() ? target : missing.back()).filename().string(), path);
}

void CheckOutputFile(const fs::path& path, const std::string& field) {
  if (path.empty()) throw Error(field, "", "a file path");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Error(field, path.string(), "a file, not a directory");
  // An output goes where the user points; a mistyped directory is an error, not created silently
  // (unlike the table cache's and bench's directories, which are theirs to create).
  fs::path parent = ParentOf(OutputTarget(path));
  if (!fs::is_directory(parent, ec))
    throw Error(field, path.string(), "a file in an existing directory (" + parent.string() +
                                          " does not exist or is not a directory)");
  CheckReplaceable(path, field);
}

}  // namespace aerial
