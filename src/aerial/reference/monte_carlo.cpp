#include "aerial/reference/monte_carlo_chunks.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
#include <thread>
#include <tuple>

namespace aerial::reference {
namespace {

uint64_t SplitMix64(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

uint64_t RotateLeft(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

template <size_t N>
void Shuffle(std::array<uint16_t, N>& perm, Rng& rng) {
  std::iota(perm.begin(), perm.end(), 0);
  for (size_t i = N - 1; i > 0; --i) std::swap(perm[i], perm[rng.Next() % (i + 1)]);
}

// Mean and standard error of the mean over independent chunk means, in chunk order so that the
// rounding does not depend on scheduling.
template <typename ChunkValue>
std::pair<double, double> MeanAndStdError(int chunks, ChunkValue&& chunk_value) {
  double sum = 0.0, sum_sq = 0.0;
  for (int c = 0; c < chunks; ++c) sum += chunk_value(c);
  double mean = sum / chunks;
  for (int c = 0; c < chunks; ++c) sum_sq += std::pow(chunk_value(c) - mean, 2);
  return {mean, std::sqrt(sum_sq / (static_cast<double>(chunks) * (chunks - 1)))};
}

}  // namespace

Rng::Rng(uint64_t seed, uint64_t stream) {
  uint64_t state = seed ^ SplitMix64(stream);
  for (uint64_t& word : s_) word = SplitMix64(state);
}

uint64_t Rng::Next() {
  uint64_t result = RotateLeft(s_[1] * 5, 7) * 9;
  uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = RotateLeft(s_[3], 45);
  return result;
}

Strata::Strata(Rng& rng) {
  Shuffle(perm_1d_, rng);
  Shuffle(perm_2d_, rng);
}

double Strata::Sample1D(int path, Rng& rng) const {
  return (perm_1d_[path] + rng.Uniform()) / kChunkPaths;
}

std::array<double, 2> Strata::Sample2D(int path, Rng& rng) const {
  int cell = perm_2d_[path];
  return {(cell % 16 + rng.Uniform()) / 16.0, (cell / 16 + rng.Uniform()) / 16.0};
}

double GroupEstimates::StdError(const Channels& weights) const {
  if (chunk_means.size() < 2) return 0.0;
  return MeanAndStdError(int(chunk_means.size()), [&](int c) {
           double sum = 0.0;
           for (int i = 0; i < weights.size(); ++i) sum += weights[i] * chunk_means[size_t(c)][i];
           return sum;
         }).second;
}

GroupOrderEstimates RunChunks(const MonteCarloOptions& options, int max_order, int channels,
                              const ChunkTracer& trace) {
  const int reported = std::min(max_order, kReportedOrders);
  const int chunks = std::max(2, (options.paths_per_query + kChunkPaths - 1) / kChunkPaths);
  const int threads = std::clamp<int>(
      options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency()),
      1, chunks);
  // means[c][k]: chunk c's mean order-k contribution.
  std::vector<std::vector<Channels>> means(chunks);
  std::atomic<int> next_chunk{0};
  auto worker = [&] {
    for (int c; (c = next_chunk.fetch_add(1)) < chunks;) {
      Rng rng(options.seed, static_cast<uint64_t>(c));
      std::vector<Channels> sums(reported + 1, Channels(channels));
      trace(c, rng, sums);
      for (Channels& s : sums)
        for (int i = 0; i < channels; ++i) s[i] /= kChunkPaths;
      means[c] = std::move(sums);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();

  GroupOrderEstimates result;
  result.chunk_totals.assign(size_t(chunks), Channels(channels));
  for (int c = 0; c < chunks; ++c)
    for (int k = 1; k <= reported; ++k)
      for (int i = 0; i < channels; ++i) result.chunk_totals[size_t(c)][i] += means[c][k][i];
  auto estimate = [&](int group, auto chunk_value) {
    Estimate e;
    for (int i = 0; i < 3; ++i)
      std::tie(e.value[i], e.std_error[i]) =
          MeanAndStdError(chunks, [&](int c) { return chunk_value(c, 3 * group + i); });
    return e;
  };
  result.groups.resize(size_t(channels / 3));
  for (int g = 0; g < channels / 3; ++g) {
    OrderEstimates& group = result.groups[size_t(g)];
    group.orders.resize(reported + 1);
    for (int k = 1; k <= reported; ++k)
      group.orders[k] = estimate(g, [&](int c, int channel) { return means[c][k][channel]; });
    group.total = estimate(g, [&](int c, int channel) { return result.chunk_totals[size_t(c)][channel]; });
  }
  return result;
}

}  // namespace aerial::reference
