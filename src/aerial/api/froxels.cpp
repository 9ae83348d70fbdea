// aerial::Froxels (include/aerial/froxels.h) over FroxelVolume.
#include <cmath>
#include <string>

#include "aerial/api/impl.h"
#include "aerial/error.h"
#include "aerial/shader_abi/camera_frame_block.h"

namespace aerial {
namespace {

void CheckCamera(const FrameCamera& camera) {
  if (camera.width == 0 || camera.height == 0)
    throw Error("camera viewport", std::to_string(camera.width) + "x" + std::to_string(camera.height),
                "a width and a height of at least 1 pixel");
  auto finite = [](const auto& values) {
    for (double v : values)
      if (!std::isfinite(v)) return false;
    return true;
  };
  if (!finite(camera.view_projection) || !finite(camera.position_m) || !finite(camera.sun_direction))
    throw Error("camera", "a value that is not finite", "finite matrices, positions and directions");
}

}  // namespace

Froxels::Impl::Impl(const vk::Context& context, const FroxelGrid& grid)
    : volume(context, grid),
      frame_block(context, vk::RecordedUniformBufferInfo(sizeof(FrameUniforms))),
      sampler(vk::CreateLinearClampSampler(context)) {}

Froxels::Froxels(const Device& device, const FroxelGrid& grid)
    : impl_(std::make_unique<Impl>(*ImplOf(device).context, grid)) {}
Froxels::~Froxels() = default;
Froxels::Froxels(Froxels&&) noexcept = default;
Froxels& Froxels::operator=(Froxels&&) noexcept = default;

void Froxels::Record(VkCommandBuffer command_buffer, const Tables& tables, const FrameCamera& camera) {
  CheckCamera(camera);
  const AtmosphereTables& atmosphere_tables = ImplOf(tables).tables();
  vk::BorrowedCommandBuffer cmd(atmosphere_tables.context(), command_buffer);
  FrameUniforms frame = MakeFrameUniforms(camera, tables.atmosphere().bottom_radius_m, grid());
  impl_->frame_block.RecordUpdate(*cmd, std::as_bytes(std::span(&frame, 1)));
  impl_->volume.Build(*cmd, atmosphere_tables, impl_->frame_block,
                      ChooseFroxelPassVariant(frame, tables.atmosphere().bottom_radius_m));
  vk::FullBarrier(*cmd);
}

const FroxelGrid& Froxels::grid() const { return impl_->volume.grid(); }
UniformBlock Froxels::frame_block() const { return {impl_->frame_block.handle(), impl_->frame_block.size()}; }
SampledImage Froxels::rayleigh() const { return ToSampledImage({&impl_->volume.rayleigh(), *impl_->sampler}); }
SampledImage Froxels::mie() const { return ToSampledImage({&impl_->volume.mie(), *impl_->sampler}); }
SampledImage Froxels::transmittance() const {
  return ToSampledImage({&impl_->volume.transmittance(), *impl_->sampler});
}

}  // namespace aerial
