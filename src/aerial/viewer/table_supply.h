#pragma once
// Which tables the viewer needs and getting them, apart from the window: the atmosphere the panel's
// knobs ask for, requests to the background worker (each asked once), and adopting what it
// finishes for the atmosphere still wanted (results for one the panel has since left are dropped).
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "aerial/tables.h"
#include "aerial/viewer/atmosphere_knobs.h"
#include "aerial/viewer/table_worker.h"

namespace aerial::viewer {

class TableSupply {
 public:
  // `base`: the atmosphere the knobs change; `variants`: the precompute options of each variant the
  // panel may switch to; `first`: the variant whose tables the caller loads itself, at start.
  TableSupply(const DeviceOptions& device, AtmosphereParameters base, std::map<LutVariant, PrecomputeOptions> variants,
              TableLoadOptions load, LutVariant first);

  // The atmosphere the tables must be made for: the base with these knobs.
  void Want(const AtmosphereKnobs& knobs);
  const AtmosphereParameters& wanted() const { return wanted_; }
  bool IsWanted(const Tables& tables) const { return tables.atmosphere().Hash() == wanted_.Hash(); }

  // Asks the worker for each needed variant that has_wanted says is missing, once per atmosphere.
  // Only tables of the base atmosphere go to the cache, so that exploring does not fill it with a
  // 32 MiB file per slider release. Returns what cannot be asked (a variant the command line's
  // table sizes do not allow).
  std::vector<std::string> Request(const std::vector<LutVariant>& needed,
                                   const std::function<bool(LutVariant)>& has_wanted);

  // The tables the worker finished for the wanted atmosphere, made on `device`; failures are added
  // to `errors`.
  std::vector<std::unique_ptr<Tables>> TakeFinished(const Device& device, std::vector<std::string>& errors);

  TableWorkStatus status() const { return worker_.status(); }

 private:
  TableWorker worker_;  // its own context, and nothing of the viewer's
  AtmosphereParameters base_, wanted_;
  std::map<LutVariant, PrecomputeOptions> variants_;
  TableLoadOptions load_;
  std::map<LutVariant, uint64_t> requested_;  // atmosphere hash asked of the worker, per variant
};

}  // namespace aerial::viewer
