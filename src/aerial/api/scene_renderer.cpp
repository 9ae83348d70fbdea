// aerial::SceneRenderer (include/aerial/renderer.h) over the Renderer.
#include "aerial/api/impl.h"

namespace aerial {

SceneRenderer::SceneRenderer(const Tables& tables, const Scene& scene, const RenderOptions& options)
    : impl_(new Impl{Renderer(tables.impl().tables(), scene, options)}) {}
SceneRenderer::~SceneRenderer() = default;
SceneRenderer::SceneRenderer(SceneRenderer&&) noexcept = default;
SceneRenderer& SceneRenderer::operator=(SceneRenderer&&) noexcept = default;

void SceneRenderer::Record(VkCommandBuffer command_buffer, const Scene& scene, uint32_t slot, bool complete) {
  vk::BorrowedCommandBuffer cmd(impl_->renderer.tables().context(), command_buffer);
  impl_->renderer.Record(*cmd, scene, slot, complete);
}

std::vector<PassTime> SceneRenderer::Render(const Scene& scene, bool complete) {
  return impl_->renderer.Render(scene, complete);
}
std::vector<PassTime> SceneRenderer::PassTimes(uint32_t slot) const { return impl_->renderer.PassTimes(slot); }
ImageRgbF SceneRenderer::ReadOutput() const { return impl_->renderer.ReadOutput(); }
SampledImage SceneRenderer::output() const {
  return ToSampledImage(impl_->renderer.tables().Sampled(impl_->renderer.output_image()));
}
const FrameInfo& SceneRenderer::frame_info() const { return impl_->renderer.frame_info(); }
const RenderOptions& SceneRenderer::options() const { return impl_->renderer.options(); }

}  // namespace aerial
