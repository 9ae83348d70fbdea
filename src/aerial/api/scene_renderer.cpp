// aerial::SceneRenderer (include/aerial/renderer.h) over the Renderer.
#include "aerial/api/impl.h"

namespace aerial {

namespace {
std::unique_ptr<SceneRenderer::Impl> MakeImpl(const Tables& tables, const Scene& scene, const RendererOptions& options) {
  return std::unique_ptr<SceneRenderer::Impl>(
      new SceneRenderer::Impl{tables, Renderer(ImplOf(tables).tables(), scene, options)});
}
}  // namespace

SceneRenderer::SceneRenderer(const Tables& tables, const Scene& scene, const RenderOptions& options)
    : SceneRenderer(MakeImpl(tables, scene, RendererOptions{options})) {}
SceneRenderer::SceneRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SceneRenderer::~SceneRenderer() = default;
SceneRenderer::SceneRenderer(SceneRenderer&&) noexcept = default;
SceneRenderer& SceneRenderer::operator=(SceneRenderer&&) noexcept = default;

SceneRenderer MakeSceneRenderer(const Tables& tables, const Scene& scene, const RendererOptions& options) {
  return ImplAccess::Make<SceneRenderer>(MakeImpl(tables, scene, options));
}

void SceneRenderer::Record(VkCommandBuffer command_buffer, const Scene& scene, uint32_t slot, bool complete) {
  vk::BorrowedCommandBuffer cmd(impl_->renderer.tables().context(), command_buffer);
  impl_->renderer.Record(*cmd, scene, slot, complete);
}

std::vector<PassTime> SceneRenderer::Render(const Scene& scene, bool complete) {
  return impl_->renderer.Render(scene, complete);
}
std::vector<PassTime> SceneRenderer::PassTimes(uint32_t slot) const { return impl_->renderer.PassTimes(slot); }
ImageRgbF SceneRenderer::ReadOutput() const { return impl_->renderer.ReadOutput(); }
void SceneRenderer::SetTerrainErrorPx(double error_px) { impl_->renderer.SetTerrainErrorPx(error_px); }
void SceneRenderer::SetRenderScale(double render_scale) { impl_->renderer.SetRenderScale(render_scale); }

SampledImage SceneRenderer::output() const {
  return SampledLikeTheTables(impl_->renderer.tables(), impl_->renderer.output_image());
}
SampledImage SceneRenderer::depth() const {
  return SampledLikeTheTables(impl_->renderer.tables(), impl_->renderer.depth_image());
}
UniformBlock SceneRenderer::frame_block(uint32_t slot) const {
  const vk::Buffer& block = impl_->renderer.frame_buffer(slot);
  return {block.handle(), block.size()};
}
SampledImage SceneRenderer::froxel_rayleigh() const {
  return SampledLikeTheTables(impl_->renderer.tables(), impl_->renderer.froxels().rayleigh());
}
SampledImage SceneRenderer::froxel_mie() const {
  return SampledLikeTheTables(impl_->renderer.tables(), impl_->renderer.froxels().mie());
}
SampledImage SceneRenderer::froxel_transmittance() const {
  return SampledLikeTheTables(impl_->renderer.tables(), impl_->renderer.froxels().transmittance());
}


const Tables& SceneRenderer::tables() const { return impl_->tables; }
const FrameInfo& SceneRenderer::frame_info() const { return impl_->renderer.frame_info(); }
const RenderOptions& SceneRenderer::options() const { return impl_->renderer.options(); }

}  // namespace aerial
