#pragma once
// Monte Carlo machinery shared by the radiance and irradiance path tracers: a seeded random
// stream per chunk of paths, per-chunk stratification, and a thread pool that runs the chunks and
// turns their means into estimates with standard errors (aerial/reference/monte_carlo.h says how).
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "aerial/reference/monte_carlo.h"
#include "aerial/reference/wavelength_groups.h"

namespace aerial::reference {

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
// Every group's OrderEstimates from the same paths, and each chunk's mean of the total at every
// channel (GroupEstimates).
struct GroupOrderEstimates {
  std::vector<OrderEstimates> groups;
  std::vector<Channels> chunk_totals;
};

// trace(chunk, rng, sums) adds, for each order k, the sum over the chunk's kChunkPaths paths of
// their order-k contributions at every channel to sums[min(k, kReportedOrders)] (sums has
// min(max_order, kReportedOrders) + 1 zeroed entries of `channels` channels). One OrderEstimates per
// group of three channels.
using ChunkTracer = std::function<void(int chunk, Rng& rng, std::vector<Channels>& sums)>;
GroupOrderEstimates RunChunks(const MonteCarloOptions& options, int max_order, int channels,
                                      const ChunkTracer& trace);

}  // namespace aerial::reference
