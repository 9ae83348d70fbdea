#include "aerial/viewer/table_supply.h"

namespace aerial::viewer {

TableSupply::TableSupply(const DeviceOptions& device, AtmosphereParameters base,
                         std::map<LutVariant, PrecomputeOptions> variants, TableLoadOptions load, LutVariant first)
    : worker_(device), base_(std::move(base)), wanted_(base_), variants_(std::move(variants)), load_(std::move(load)) {
  requested_[first] = base_.Hash();
}

void TableSupply::Want(const AtmosphereKnobs& knobs) { wanted_ = ApplyKnobs(base_, knobs); }

std::vector<std::string> TableSupply::Request(const std::vector<LutVariant>& needed,
                                              const std::function<bool(LutVariant)>& has_wanted) {
  std::vector<std::string> unavailable;
  for (LutVariant variant : needed) {
    if (has_wanted(variant) || requested_[variant] == wanted_.Hash()) continue;
    requested_[variant] = wanted_.Hash();  // asked once, whatever comes of it
    auto options = variants_.find(variant);
    if (options == variants_.end()) {
      unavailable.push_back(ToString(variant) + " tables are not available with the command line's table sizes");
      continue;
    }
    TableLoadOptions load = load_;
    load.write_cache = wanted_.Hash() == base_.Hash();
    worker_.Submit({.slot = int(variant), .atmosphere = wanted_, .options = options->second, .load = load});
  }
  return unavailable;
}

std::vector<std::unique_ptr<Tables>> TableSupply::TakeFinished(const Device& device, std::vector<std::string>& errors) {
  std::vector<std::unique_ptr<Tables>> finished;
  while (std::optional<TableResult> result = worker_.TakeResult()) {
    if (!result->tables) {
      errors.push_back("tables: " + result->error);
      continue;
    }
    if (result->request.atmosphere.Hash() != wanted_.Hash()) continue;
    finished.push_back(std::make_unique<Tables>(Tables::FromSnapshot(device, *result->tables)));
  }
  return finished;
}

}  // namespace aerial::viewer
