#pragma once
// The reference's Monte Carlo estimates and their options (the machinery that computes them is
// monte_carlo_chunks.h).
//
// Paths are traced in chunks of kChunkPaths. Chunk c draws from its own stream (seed, c), so the
// result depends on the seed and the path count but not on the thread count or scheduling. The
// first two sampling dimensions of each chunk are stratified (256 strata in 1D and 16 x 16 in
// 2D, randomly paired), which makes paths within a chunk dependent: the standard error is
// therefore computed from the spread of the chunk means, which are independent.
#include <cstdint>
#include <limits>
#include <vector>

#include "aerial/atmosphere.h"
#include "aerial/reference/wavelength_groups.h"

namespace aerial::reference {

struct Estimate {
  Spectrum value{};
  Spectrum std_error{};  // one standard deviation of `value`'s Monte Carlo error.
};

// Estimates at several groups of three wavelengths from the same paths (wavelength_groups.h).
// Each group's std_error is right for its own channels, but the groups' errors are correlated: the
// standard error of a weighted sum over channels of several groups comes from the chunks' means of
// that sum, which are independent (StdError).
struct GroupEstimates {
  std::vector<Estimate> groups;
  std::vector<Channels> chunk_means;  // each chunk's mean at every channel; empty: no Monte Carlo part
  // Of sum_c weights[c] value[c]; 0 without chunks.
  double StdError(const Channels& weights) const;
};

struct MonteCarloOptions {
  // 131072 paths: standard error <= ~0.15% of the radiance of orders 1..4 at daylight points
  // (0.1% typical), ~1.4 s of CPU (0.7 s on 2 cores) per Earth radiance query.
  int paths_per_query = 131072;  // rounded up to a multiple of kChunkPaths, at least 2 chunks.
  uint64_t seed = 1;
  int threads = 0;  // 0: std::thread::hardware_concurrency().
  // Russian roulette from this path vertex on (path_tracer.h); kAllOrders: never.
  int roulette_from_order = 4;
};

inline constexpr int kChunkPaths = 256;

// max_order for the whole series: paths go on until Russian roulette ends them (path_tracer.h).
inline constexpr int kAllOrders = std::numeric_limits<int>::max();
// Orders are reported one by one up to this one; the estimate of the last reported order holds
// the sum of it and all higher orders.
inline constexpr int kReportedOrders = 12;

}  // namespace aerial::reference
