#pragma once
// Monte Carlo machinery shared by the radiance and irradiance path tracers: options, a seeded
// random stream per chunk of paths, per-chunk stratification, and a thread pool that runs the
// chunks and turns their means into estimates with standard errors.
//
// Paths are traced in chunks of kChunkPaths. Chunk c draws from its own stream (seed, c), so the
// result depends on the seed and the path count but not on the thread count or scheduling. The
// first two sampling dimensions of each chunk are stratified (256 strata in 1D and 16 x 16 in
// 2D, randomly paired), which makes paths within a chunk dependent: the standard error is
// therefore computed from the spread of the chunk means, which are independent.
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "aerial/atmosphere.h"

namespace aerial::reference {

struct Estimate {
  Spectrum value{};
  Spectrum std_error{};  // one standard deviation of `value`'s Monte Carlo error.
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

// xoshiro256** (Blackman & Vigna 2018), seeded through splitmix64.
class Rng {
 public:
  Rng(uint64_t seed, uint64_t stream);
  uint64_t Next();
  double Uniform() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }  // [0, 1).

 private:
  std::array<uint64_t, 4> s_;
};

// Jittered strata for one chunk: path i gets the 1D stratum perm_1d[i] of 256 and the 2D cell
// perm_2d[i] of a 16 x 16 grid, both random permutations.
class Strata {
 public:
  explicit Strata(Rng& rng);
  double Sample1D(int path, Rng& rng) const;
  std::array<double, 2> Sample2D(int path, Rng& rng) const;

 private:
  std::array<uint16_t, kChunkPaths> perm_1d_, perm_2d_;
};

// Per-order estimates: orders[k] for k in [1, min(max_order, kReportedOrders)] (orders[0] unused;
// the last one includes the orders above it), and their sum.
struct OrderEstimates {
  std::vector<Estimate> orders;
  Estimate total;
};

// trace(chunk, rng, sums) adds, for each order k, the sum over the chunk's kChunkPaths paths of
// their order-k contributions to sums[min(k, kReportedOrders)] (sums has
// min(max_order, kReportedOrders) + 1 zeroed entries).
using ChunkTracer = std::function<void(int chunk, Rng& rng, std::vector<Spectrum>& sums)>;
OrderEstimates RunChunks(const MonteCarloOptions& options, int max_order, const ChunkTracer& trace);

}  // namespace aerial::reference
