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
// the file it points to is replaced and the link kept; a directory, device, FIFO or socket is
// refused by name, never replaced. Temporaries a killed writer of path left are removed first, and
// this write's own one if SIGINT, SIGTERM or SIGHUP ends the program (core/live_temporary.h).
void WriteFileAtomically(const std::filesystem::path& path, std::span<const std::byte> bytes);
void WriteFileAtomically(const std::filesystem::path& path, std::string_view text);

// Removes the temporaries that writes into directory left when their process died mid-write
// (kill -9, a crash, a power cut): files named exactly as WriteFileAtomically names them,
// "<target>.tmp-<pid>-<16 hex digits>", whose target name starts with target_prefix and whose pid
// is no running process (kill(pid, 0) fails with ESRCH). A live or reused pid keeps its file.
// Returns the removed paths; a directory that cannot be listed gives none.
std::vector<std::filesystem::path> RemoveStaleTemporaries(const std::filesystem::path& directory,
                                                          std::string_view target_prefix);

// Reads the whole file.
std::vector<std::byte> ReadFile(const std::filesystem::path& path);

// Checks, before any long work, that WriteFileAtomically(path, ...) can succeed: the parent
// directory exists (it is created if missing) and a file can be created in it, and path is
// neither a directory nor a special file. It cannot foresee a full disk.
void CheckWritable(const std::filesystem::path& path);

// The same check for an output file the user names (field: the option, "--stats"), which must
// lie in an existing directory: nothing is created. An empty path is refused too.
void CheckOutputFile(const std::filesystem::path& path, const std::string& field);

}  // namespace aerial
