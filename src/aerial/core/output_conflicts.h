#pragma once
// One command's outputs must be files of their own: no output may be the same file as another
// output or as a file the command reads, directly or through a symbolic or hard link. Otherwise
// one output replaces the other (`view --stats s.png --screenshot s.png` left JSON in the
// picture), or the command replaces its own input. Every command checks its outputs here, after
// reading its inputs and before any work.
#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <vector>

namespace aerial {

// A file under the option or role that names it ("--stats" from a command, "table cache").
struct NamedFile {
  std::string field;
  std::filesystem::path path;
};

// Records that this process read path (opened as `info`) as an input named field. Every file
// read through ReadBoundedFile (core/bounded_file.h) is recorded: configs, scenes, camera paths,
// glTF models and their buffers.
void RecordInputFile(const std::string& field, const std::filesystem::path& path, const struct stat& info);

// Throws Error(output's field, its path, "a file other than <field> <path> ...") for the first
// output (empty paths are skipped) that is the same file as an earlier output or as a recorded
// input. An output that exists is compared by device and inode (so links to it are found); one
// that does not yet is compared by where it will be written (through its links, dangling ones
// included: atomic_file.h's OutputTarget), made absolute.
void CheckOutputConflicts(const std::vector<NamedFile>& outputs);

}  // namespace aerial
