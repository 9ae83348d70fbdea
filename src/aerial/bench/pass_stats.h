#pragma once
// Statistics over repeated precompute runs or frames. The machine is noisy (2 cores shared with other
// work, lavapipe running the "GPU" on them), so a benchmark reports the median of each pass with
// its min and max instead of a mean that one disturbed run would drag.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "aerial/device.h"

namespace aerial::bench {

// One Precompute call or one frame: the GPU time of each pass and, for a Precompute, the
// wall-clock time of the whole call (which also covers pipeline creation, allocation and
// submissions).
struct RunResult {
  std::vector<PassTime> passes;
  double wall_ms = 0.0;
  // CPU time of the whole process over the run (frames only): lavapipe's threads and the caller's.
  // Other processes on the machine lengthen wall and GPU times but barely this, so it tells a
  // cost apart from noise on a shared machine.
  double cpu_ms = 0.0;
  // CPU time of the calling thread over the frame: the renderer's own work (terrain and shadow
  // caster selection, sorting, recording, submitting) without the driver's threads, which on
  // lavapipe are the GPU. On a real GPU this is most of what a frame costs the CPU.
  double caller_cpu_ms = 0.0;
  // Tiles of the sun's shadow map that the frame redrew whole and in part
  // (FrameInfo::shadow_tiles_redrawn, ::shadow_tile_regions_redrawn).
  int shadow_tiles_redrawn = 0, shadow_tile_regions_redrawn = 0;
  // Draw calls and pipeline binds the frame recorded (FrameInfo::draws, ::draw_binds).
  int draws = 0, draw_binds = 0;
  double GpuMs() const;
};

// One value per run: the summed GPU time of its passes, its wall-clock time, or its CPU time (the
// process's or the calling thread's).
std::vector<double> GpuTotals(const std::vector<RunResult>& runs);
std::vector<double> WallTotals(const std::vector<RunResult>& runs);
std::vector<double> CpuTotals(const std::vector<RunResult>& runs);
std::vector<double> CallerCpuTotals(const std::vector<RunResult>& runs);
std::vector<double> DrawCounts(const std::vector<RunResult>& runs);
std::vector<double> DrawBindCounts(const std::vector<RunResult>& runs);
// A count per run (e.g. &RunResult::shadow_tiles_redrawn), on average.
double MeanPerRun(const std::vector<RunResult>& runs, int RunResult::*count);
// The median over runs of the named pass's fragment-shader invocations (summed within a run where
// it ran more than once); nullopt where the device did not count them or the pass never ran.
std::optional<double> MedianFragmentInvocations(const std::vector<RunResult>& runs, const std::string& pass);

struct Stats {
  double median = 0.0, min = 0.0, max = 0.0;
};
Stats Summarize(std::vector<double> values);  // values must not be empty
// The median over runs of numerators[i] / denominators[i]: where two configurations' runs take
// turns, each pair saw the same stretch of a noisy machine, which a ratio of their medians does
// not cancel. The two must be as long, and not empty.
double MedianPairedRatio(const std::vector<double>& numerators, const std::vector<double>& denominators);

// The values of one named quantity, one per run.
struct Series {
  std::string name;
  std::vector<double> ms;
};

// Sums the pass times of each run by key(pass name), keeping the keys in order of first
// appearance; passes whose key is empty are left out. Summing within a run before taking the
// median over runs keeps each run's passes together (a median of sums, not a sum of medians).
std::vector<Series> GroupPasses(const std::vector<RunResult>& runs,
                                const std::function<std::string(const std::string&)>& key);

// The summed time of the named passes in each run. Throws aerial::Error if a name is timed in no
// run (a renamed pass must not silently count as 0 ms); label names the series.
Series SumOfPasses(const std::vector<RunResult>& runs, const std::vector<std::string>& passes,
                   const std::string& label);

// "scattering density (order 3)" -> "scattering density": the kind of pass, whatever the order
// (and whatever the spectral precompute's group: "[2/4] scattering density (order 3)" too).
std::string PassKind(const std::string& pass);

}  // namespace aerial::bench
