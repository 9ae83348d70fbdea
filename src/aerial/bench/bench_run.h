#pragma once
// The whole `aerial bench` measurement in one process: precompute every tier of both variants
// (runs interleaved), time frames with each tier's tables, sample the CPU reference in every
// view, then measure every tier's accuracy against it and against each other.
#include "aerial/bench/bench_plan.h"
#include "aerial/bench/bench_results.h"
#include "aerial/device.h"

namespace aerial::bench {

// quiet: no progress bar (it is only drawn on a terminal anyway).
BenchResults RunBench(const BenchPlan& plan, const Device& device, const MachineInfo& machine,
                      bool quiet);

}  // namespace aerial::bench
