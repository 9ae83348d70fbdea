#pragma once
// What a write is making (core/atomic_file.h): its temporary, and the directories it created for
// the output, removed when SIGINT, SIGTERM or SIGHUP ends the program mid-write, newest first. So
// Ctrl-C during export-vdb leaves no "out.vdb.tmp-*" behind, and a SIGTERM'd bench no empty
// --out directory chain. (A SIGKILL'd writer's temporary is removed by a later write to the same
// directory instead: RemoveStaleTemporaries.)
//
// The handler, installed with the first LiveTemporary for each of those signals whose disposition
// is still the default (one a program or nohup chose is kept), unlinks every registered entry,
// which is async-signal-safe, then lets the signal end the program as it would have. At the same
// time SIGXFSZ, whose default action kills the program without a word when a write passes the
// file size limit (`ulimit -f`), is ignored (unless a program chose another disposition): such a
// write then fails with EFBIG, which the writer reports by name and cleans up after.
#include <string>

namespace aerial {

class LiveTemporary {
 public:
  // Registers the entry name of the directory open as directory_fd, which must stay open while
  // registered: a file this process just created, or with is_directory a directory it just made
  // (removed only while it is empty). A name over 255 bytes, or a 33rd entry at once, is not
  // registered (left to a later run).
  LiveTemporary(int directory_fd, const std::string& name, bool is_directory = false);
  // Unregisters it: by then the writer has renamed or removed the file, or written into the
  // directory.
  ~LiveTemporary();
  LiveTemporary(const LiveTemporary&) = delete;
  LiveTemporary& operator=(const LiveTemporary&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace aerial
