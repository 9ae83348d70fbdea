#pragma once
// Temporaries that are being written (core/atomic_file.h), removed when SIGINT, SIGTERM or SIGHUP
// ends the program mid-write: Ctrl-C during export-vdb must not leave "out.vdb.tmp-*" behind.
// (A SIGKILL'd writer's temporary is removed by the next write to the same path instead:
// RemoveStaleTemporaries.)
//
// The handler, installed with the first LiveTemporary for each of those signals whose disposition
// is still the default (one a program or nohup chose is kept), unlinks every registered path,
// which is async-signal-safe, then lets the signal end the program as it would have.
#include <filesystem>

namespace aerial {

class LiveTemporary {
 public:
  // Registers path (a temporary this process just created); a path that does not fit the
  // registry (32 paths of up to 4095 bytes) is left to the next run.
  explicit LiveTemporary(const std::filesystem::path& path);
  // Unregisters it: by then the writer has renamed or removed the file.
  ~LiveTemporary();
  LiveTemporary(const LiveTemporary&) = delete;
  LiveTemporary& operator=(const LiveTemporary&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace aerial
