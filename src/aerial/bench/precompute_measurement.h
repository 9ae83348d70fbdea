#pragma once
// Precompute runs of several table options in one process, interleaved (run i measures every
// option in turn) so that all of them see the same machine noise. The first Precompute of a
// process also pays lavapipe's JIT compilation of every pipeline (tens to hundreds of ms per
// pass), so warm-up runs come first and the first of them is kept apart as the cold time.
#include <functional>
#include <memory>
#include <vector>

#include "aerial/atmosphere.h"
#include "aerial/bench/precompute_report.h"
#include "aerial/device.h"
#include "aerial/tables.h"

namespace aerial::bench {

struct PrecomputeMeasurement {
  BenchResult result;
  std::unique_ptr<Tables> tables;  // the last run's, ready to render with
};

// Called after every run, warm-up or measured; index counts from 1 within each kind.
using PrecomputeRunCallback =
    std::function<void(const BenchResult& result, const RunResult& run, bool warming, int index)>;

// One measurement per option, in the order given. on_run may be empty.
std::vector<PrecomputeMeasurement> MeasurePrecompute(const Device& device,
                                                     const AtmosphereParameters& atmosphere,
                                                     const std::vector<PrecomputeOptions>& options,
                                                     int warmup, int runs,
                                                     const PrecomputeRunCallback& on_run);

}  // namespace aerial::bench
