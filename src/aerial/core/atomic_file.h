#pragma once
// Whole-file I/O for outputs that take long to make (table caches, images, reports). A reader
// must never see half a file, even if the program is killed mid-write or the disk fills up, so
// every write goes to a temporary in the same directory and is renamed over the target (rename(2)
// is atomic within one file system). Failures throw aerial::Error naming the path and the OS
// reason.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace aerial {

// Writes bytes to path atomically: path then holds either its old content or all of bytes.
// Missing parent directories are created. The data is fsync'ed before the rename, and the
// directory after it, so the new content also survives a power cut. A regular file at path is
// replaced keeping its mode and (where the process may set it) its owner; through a symbolic link,
// even one whose file does not exist yet, the file it points to is written and the link kept; a
// directory, device, FIFO or socket is refused by name, never replaced. The temporary is
// "<name>.tmp-<pid>-<16 hex digits>" beside the file, the name cut short when the whole would be too
// long, so any valid name can be written. Temporaries that killed writers of path left are
// removed first, and this write's own one (with the directories it made) if SIGINT, SIGTERM or
// SIGHUP ends the program (core/live_temporary.h). A write past the file size limit fails with
// EFBIG, named as such, instead of SIGXFSZ killing the program.
void WriteFileAtomically(const std::filesystem::path& path, std::span<const std::byte> bytes);
void WriteFileAtomically(const std::filesystem::path& path, std::string_view text);

// Removes the temporaries that writes into directory left when their process died mid-write
// (kill -9, a crash, a power cut): regular files named as WriteFileAtomically names them, whose
// target name starts with target_prefix, and whose writer's lock is gone. Every writer holds an
// exclusive flock(2) on its temporary until the rename, which the kernel releases however the
// writer ends; so a temporary is removed only when provably stale, whatever pid namespace or host
// its writer runs in (on a file system without locks, none is removed). Returns the removed paths;
// a directory that cannot be listed gives none.
std::vector<std::filesystem::path> RemoveStaleTemporaries(const std::filesystem::path& directory,
                                                          std::string_view target_prefix);

// Reads the whole file.
std::vector<std::byte> ReadFile(const std::filesystem::path& path);

// Checks, before any long work, that WriteFileAtomically(path, ...) can succeed, making nothing:
// path is neither a directory nor a special file, and a file can be created in its directory or,
// when that is missing, in the nearest directory above it (where the write will make the rest).
// It cannot foresee a full disk.
void CheckWritable(const std::filesystem::path& path);

// The same check for an output file the caller names (field: what names it, "VDB path"), which must
// lie in an existing directory (through a symbolic link, the file it points to must): nothing is
// created. An empty path is refused too.
void CheckOutputFile(const std::filesystem::path& path, const std::string& field);

// The file a write to path replaces or makes: path itself, or through symbolic links, dangling
// ones included, the path they lead to (not made canonical).
std::filesystem::path OutputTarget(const std::filesystem::path& path);

}  // namespace aerial
