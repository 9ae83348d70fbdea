#pragma once
// Table sets made off the viewer's thread, so the window keeps drawing while a precompute runs
// (seconds to tens of seconds on lavapipe). The worker has its own aerial::Device, with its own
// device and queue: its submissions never touch the viewer's queue (a VkQueue must not be used
// from two threads at once). Finished tables come back as a TableSnapshot (host memory), which
// the viewer makes tables on its own device from (Tables::FromSnapshot): the same hand-over as a
// cache file, without the file.
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "aerial/tables.h"

namespace aerial::viewer {

struct TableRequest {
  int slot = 0;  // what the tables are for; a newer queued request for the same slot replaces it
  AtmosphereParameters atmosphere;
  PrecomputeOptions options;
  TableLoadOptions load;  // cache directory and use; progress is reported through status()
};

struct TableResult {
  TableRequest request;
  std::optional<TableSnapshot> tables;  // unset on failure
  std::string error;                 // why, on failure
};

struct TableWorkStatus {
  bool busy = false;
  int done_steps = 0, total_steps = 0;  // precompute passes; 0 of 0 until the first is done
  std::string description;              // of the running request
};

class TableWorker {
 public:
  explicit TableWorker(DeviceOptions device_options);
  // Waits for the running request: a precompute cannot be interrupted.
  ~TableWorker();
  TableWorker(const TableWorker&) = delete;
  TableWorker& operator=(const TableWorker&) = delete;

  void Submit(TableRequest request);
  // The oldest finished request, if any.
  std::optional<TableResult> TakeResult();
  TableWorkStatus status() const;

 private:
  void Run();
  TableResult Make(TableRequest request);

  DeviceOptions device_options_;
  std::unique_ptr<Device> device_;  // created by the worker thread on its first request
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<TableRequest> queued_;
  std::deque<TableResult> finished_;
  TableWorkStatus status_;
  bool stopping_ = false;
  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace aerial::viewer
