#include "aerial/bench/full_screen_tap.h"

namespace aerial::bench {

FullScreenTap::FullScreenTap(const vk::Context& context, uint32_t width, uint32_t height,
                             const SampledImage& volume)
    : context_(context),
      volume_(volume),
      target_(context, {.extent = {width, height, 1},
                        .usage = ::vk::ImageUsageFlagBits::eColorAttachment}),
      sampler_(vk::CreateLinearClampSampler(context)),
      pipeline_(context, {.vertex_shader = "frame/fullscreen.vert",
                          .fragment_shader = "bench/full_screen_tap.frag",
                          .slots = {{"volume", vk::kSampled}},
                          .push_constant_bytes = 2 * sizeof(float),
                          .color_formats = {::vk::Format::eR32G32B32A32Sfloat}}),
      timer_(context) {
  context.Submit([&](const auto& cmd) { target_.InitializeLayout(cmd); });
}

std::vector<PassTime> FullScreenTap::Run() {
  float size[2] = {float(target_.extent().width), float(target_.extent().height)};
  context_.Submit([&](const vk::CommandBuffer& cmd) {
    timer_.Reset(cmd);
    timer_.Begin(cmd, "full-screen tap");
    {
      vk::Rendering rendering(cmd, {.colors = {&target_}, .clear_colors = {std::nullopt}});
      pipeline_.Bind(cmd, {vk::SampledViewSlot{volume_.view, *sampler_}}, size);
      vk::DrawGeneratedTriangle(cmd);
    }
    timer_.End(cmd);
    vk::FullBarrier(cmd);
  });
  return timer_.Collect();
}

}  // namespace aerial::bench
