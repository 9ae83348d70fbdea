#include "aerial/vk/gpu_timer.h"

#include "aerial/error.h"

namespace aerial::vk {

GpuTimer::GpuTimer(const Context& context, uint32_t max_passes)
    : context_(context),
      pool_(context.device(), ::vk::QueryPoolCreateInfo{.queryType = ::vk::QueryType::eTimestamp,
                                                        .queryCount = 2 * max_passes}),
      capacity_(max_passes) {
  if (context.pipeline_statistics())
    statistics_.emplace(context.device(),
                        ::vk::QueryPoolCreateInfo{
                            .queryType = ::vk::QueryType::ePipelineStatistics,
                            .queryCount = max_passes,
                            .pipelineStatistics = ::vk::QueryPipelineStatisticFlagBits::eFragmentShaderInvocations});
}

void GpuTimer::Reset(const CommandBuffer& cmd) {
  cmd.resetQueryPool(*pool_, 0, 2 * capacity_);
  if (statistics_) cmd.resetQueryPool(**statistics_, 0, capacity_);
  passes_.clear();
}

void GpuTimer::Begin(const CommandBuffer& cmd, std::string pass) {
  if (passes_.size() >= capacity_)
    throw Error("timed passes", std::to_string(passes_.size() + 1), "at most " + std::to_string(capacity_));
  cmd.writeTimestamp(::vk::PipelineStageFlagBits::eTopOfPipe, *pool_, uint32_t(2 * passes_.size()));
  if (statistics_) cmd.beginQuery(**statistics_, uint32_t(passes_.size()));
  passes_.push_back(std::move(pass));
}

void GpuTimer::End(const CommandBuffer& cmd) {
  if (statistics_) cmd.endQuery(**statistics_, uint32_t(passes_.size() - 1));
  cmd.writeTimestamp(::vk::PipelineStageFlagBits::eBottomOfPipe, *pool_,
                     uint32_t(2 * passes_.size() - 1));
}

std::vector<PassTime> GpuTimer::Collect() const {
  std::vector<PassTime> times;
  if (passes_.empty()) return times;
  auto [result, ticks] = pool_.getResults<uint64_t>(
      0, uint32_t(2 * passes_.size()), 2 * passes_.size() * sizeof(uint64_t), sizeof(uint64_t),
      ::vk::QueryResultFlagBits::e64 | ::vk::QueryResultFlagBits::eWait);
  if (result != ::vk::Result::eSuccess)
    throw Error("timestamp queries", ::vk::to_string(result), "VK_SUCCESS");
  for (size_t i = 0; i < passes_.size(); ++i) {
    double ns = double(ticks[2 * i + 1] - ticks[2 * i]) * context_.timestamp_period_ns();
    times.push_back({passes_[i], ns * 1e-6});
  }
  if (!statistics_) return times;
  auto [counted, invocations] = statistics_->getResults<uint64_t>(
      0, uint32_t(passes_.size()), passes_.size() * sizeof(uint64_t), sizeof(uint64_t),
      ::vk::QueryResultFlagBits::e64 | ::vk::QueryResultFlagBits::eWait);
  if (counted != ::vk::Result::eSuccess)
    throw Error("pipeline statistics queries", ::vk::to_string(counted), "VK_SUCCESS");
  for (size_t i = 0; i < passes_.size(); ++i) times[i].fragment_shader_invocations = invocations[i];
  return times;
}

}  // namespace aerial::vk
