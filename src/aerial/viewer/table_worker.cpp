#include "aerial/viewer/table_worker.h"

#include <algorithm>

#include "aerial/error.h"

namespace aerial::viewer {

TableWorker::TableWorker(DeviceOptions device_options)
    : device_options_(std::move(device_options)), thread_([this] { Run(); }) {}

TableWorker::~TableWorker() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    queued_.clear();
  }
  wake_.notify_all();
  thread_.join();
}

void TableWorker::Submit(TableRequest request) {
  {
    std::lock_guard lock(mutex_);
    std::erase_if(queued_, [&](const TableRequest& r) { return r.slot == request.slot; });
    queued_.push_back(std::move(request));
  }
  wake_.notify_all();
}

std::optional<TableResult> TableWorker::TakeResult() {
  std::lock_guard lock(mutex_);
  if (finished_.empty()) return std::nullopt;
  TableResult result = std::move(finished_.front());
  finished_.pop_front();
  return result;
}

TableWorkStatus TableWorker::status() const {
  std::lock_guard lock(mutex_);
  return status_;
}

void TableWorker::Run() {
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [&] { return stopping_ || !queued_.empty(); });
    if (stopping_) return;
    TableRequest request = std::move(queued_.front());
    queued_.pop_front();
    status_ = {.busy = true,
               .description = request.atmosphere.name + ", " + ToString(request.options.variant)};
    lock.unlock();
    TableResult result = Make(std::move(request));
    lock.lock();
    finished_.push_back(std::move(result));
    status_ = {};
  }
}

TableResult TableWorker::Make(TableRequest request) {
  TableResult result{.request = request};
  request.load.progress = [this](int done, int total, std::string_view) {
    std::lock_guard lock(mutex_);
    status_.done_steps = done;
    status_.total_steps = total;
  };
  try {
    if (!device_) device_ = std::make_unique<Device>(device_options_);
    result.tables = Tables::LoadOrPrecompute(*device_, request.atmosphere, request.options, request.load).Snapshot();
  } catch (const std::exception& e) {
    result.error = e.what();
  }
  return result;
}

}  // namespace aerial::viewer
