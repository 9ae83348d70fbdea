#include "aerial/render/renderer.h"

#include <array>

#include "aerial/core/error.h"

namespace aerial {
namespace {

int32_t PerPixel(AerialMode mode) { return mode == AerialMode::kPerPixel ? 1 : 0; }

vk::GraphicsPipelineCreateInfo MeshPipeline(const std::string& vertex, const std::string& fragment,
                                            std::vector<::vk::DescriptorType> slots, bool blended,
                                            AerialMode mode) {
  return {.vertex_shader = vertex,
          .fragment_shader = fragment,
          .slot_types = std::move(slots),
          .vertex_stride = sizeof(Vertex),
          .attributes = {{::vk::Format::eR32G32B32Sfloat, offsetof(Vertex, position)},
                         {::vk::Format::eR32G32B32Sfloat, offsetof(Vertex, normal)},
                         {::vk::Format::eR32G32B32Sfloat, offsetof(Vertex, albedo)},
                         {::vk::Format::eR32Sfloat, offsetof(Vertex, opacity)}},
          .color_formats = {::vk::Format::eR32G32B32A32Sfloat},
          .depth_format = ::vk::Format::eD32Sfloat,
          .depth_write = !blended,
          .alpha_blend = blended,
          .specialization = {PerPixel(mode)}};
}

// The composite is two full-screen passes split by the depth buffer (reversed Z, cleared to 0):
// EQUAL 0 keeps the sky pixels, LESS (0 < stored depth) the pixels with geometry. Each pixel then
// runs only its own shader; in one shader a CPU rasterizer runs both sides of the branch.
vk::GraphicsPipelineCreateInfo CompositePipeline(AerialMode mode, const std::string& fragment,
                                                 ::vk::CompareOp depth_compare, size_t samplers) {
  std::vector<::vk::DescriptorType> slots = {vk::kUniform, vk::kUniform};
  slots.insert(slots.end(), samplers, vk::kSampled);
  return {.vertex_shader = "frame/fullscreen.vert",
          .fragment_shader = fragment,
          .slot_types = slots,
          .vertex_stride = 16,
          .attributes = {{::vk::Format::eR32G32B32A32Sfloat, 0}},
          .color_formats = {::vk::Format::eR32G32B32A32Sfloat},
          .depth_format = ::vk::Format::eD32Sfloat,
          .depth_write = false,
          .depth_compare = depth_compare,
          .specialization = {PerPixel(mode)}};
}

vk::Buffer HostBuffer(const vk::Context& context, std::span<const std::byte> bytes,
                      ::vk::BufferUsageFlags usage) {
  vk::Buffer buffer(context, {.size = bytes.size(), .usage = usage, .host_visible = true});
  buffer.Write(bytes);
  return buffer;
}

// One triangle covering the screen: (-1,-1), (3,-1), (-1,3) in clip space.
constexpr std::array<float, 12> kFullscreenTriangle = {-1, -1, 0, 1, 3, -1, 0, 1, -1, 3, 0, 1};
constexpr std::array<uint32_t, 3> kFullscreenIndices = {0, 1, 2};

// The sky-view table's size (Hillaire 2020 uses 192x108): azimuth over [0, pi], zenith split at
// the horizon (54 rows each side).
constexpr std::array<int, 2> kSkyViewSize = {192, 108};

vk::ImageCreateInfo SkyViewImage() {
  return {.extent = {uint32_t(kSkyViewSize[0]), uint32_t(kSkyViewSize[1]), 1}};
}

vk::ImageCreateInfo Target(const RenderOptions& o, ::vk::Format format, ::vk::ImageUsageFlags usage) {
  return {.extent = {uint32_t(o.width), uint32_t(o.height), 1}, .format = format, .usage = usage};
}

}  // namespace

void RenderOptions::Validate() const {
  CheckImageSize(width, height, "--width/--height");
  froxels.Validate();
}

using vk::kSampled;
using vk::kUniform;

Renderer::Renderer(const AtmosphereTables& tables, const Scene& scene, const RenderOptions& options)
    : tables_(tables),
      options_((options.Validate(), options)),
      geometry_(tables.context(), scene),
      froxels_(tables.context(), options.froxels),
      frame_buffer_(tables.context(), {.size = sizeof(FrameUniforms),
                                       .usage = ::vk::BufferUsageFlagBits::eUniformBuffer,
                                       .host_visible = true}),
      surface_(tables.context(), Target(options, ::vk::Format::eR32G32B32A32Sfloat,
                                        ::vk::ImageUsageFlagBits::eColorAttachment |
                                            ::vk::ImageUsageFlagBits::eSampled |
                                            ::vk::ImageUsageFlagBits::eTransferSrc)),
      depth_(tables.context(), Target(options, ::vk::Format::eD32Sfloat,
                                      ::vk::ImageUsageFlagBits::eDepthStencilAttachment)),
      output_(tables.context(), Target(options, ::vk::Format::eR32G32B32A32Sfloat,
                                       ::vk::ImageUsageFlagBits::eColorAttachment |
                                           ::vk::ImageUsageFlagBits::eSampled |
                                           ::vk::ImageUsageFlagBits::eTransferSrc)),
      sky_rayleigh_(tables.context(), SkyViewImage()),
      sky_mie_(tables.context(), SkyViewImage()),
      sky_background_(tables.context(), SkyViewImage()),
      sky_view_(tables.context(), "frame/sky_view.comp",
                {vk::kUniform, vk::kUniform, vk::kSampled, vk::kSampled, vk::kSampled, vk::kSampled,
                 vk::kSampled, vk::kStorageImage, vk::kStorageImage, vk::kStorageImage},
                sizeof(kSkyViewSize)),
      opaque_(tables.context(), MeshPipeline("frame/opaque.vert", "frame/opaque.frag",
                                             {kUniform, kUniform, kSampled, kSampled}, false,
                                             options.mode)),
      transparent_(tables.context(),
                   MeshPipeline("frame/transparent.vert", "frame/transparent.frag",
                                {kUniform, kUniform, kSampled, kSampled, kSampled, kSampled,
                                 kSampled, kSampled, kSampled, kSampled},
                                true, options.mode)),
      composite_sky_(tables.context(), CompositePipeline(options.mode, "frame/composite_sky.frag",
                                                         ::vk::CompareOp::eEqual, 8)),
      composite_surface_(tables.context(),
                         CompositePipeline(options.mode, "frame/composite_surface.frag",
                                           ::vk::CompareOp::eLess, 8)),
      fullscreen_vertices_(HostBuffer(tables.context(), std::as_bytes(std::span(kFullscreenTriangle)),
                                      ::vk::BufferUsageFlagBits::eVertexBuffer)),
      fullscreen_indices_(HostBuffer(tables.context(), std::as_bytes(std::span(kFullscreenIndices)),
                                     ::vk::BufferUsageFlagBits::eIndexBuffer)),
      timer_(std::make_unique<vk::GpuTimer>(tables.context())) {
  tables.context().Submit([&](const auto& cmd) {
    for (const vk::Image* image : {&surface_, &depth_, &output_, &sky_rayleigh_, &sky_mie_,
                                   &sky_background_})
      image->InitializeLayout(cmd);
  });
}

Renderer::~Renderer() = default;

std::vector<vk::PassTime> Renderer::Render(const Scene& scene) {
  frame_uniforms_ = MakeFrameUniforms(scene, tables_.atmosphere().bottom_radius_m, options_.width,
                                      options_.height, options_.froxels);
  frame_buffer_.Write(std::as_bytes(std::span(&frame_uniforms_, 1)));
  geometry_.SortTransparent(scene.camera.position);
  ::vk::Sampler sampler = tables_.sampler();
  auto sampled = [&](const vk::Image& image) { return vk::SampledImageSlot{&image, sampler}; };
  vk::Slot atmosphere = vk::UniformBufferSlot{&tables_.uniform_buffer()};
  vk::Slot frame = vk::UniformBufferSlot{&frame_buffer_};
  tables_.context().Submit([&](const ::vk::raii::CommandBuffer& cmd) {
    timer_->Reset(cmd);
    if (options_.mode == AerialMode::kFroxel) {
      timer_->Begin(cmd, "froxel build");
      froxels_.Build(cmd, tables_, frame_buffer_);
      timer_->End(cmd);
      timer_->Begin(cmd, "sky view");
      sky_view_.Dispatch(cmd,
                         {atmosphere, frame, sampled(tables_.transmittance()), sampled(tables_.rayleigh()),
                          sampled(tables_.mie()), sampled(tables_.multiple()),
                          sampled(tables_.irradiance()), vk::StorageImageSlot{&sky_rayleigh_}, vk::StorageImageSlot{&sky_mie_},
                          vk::StorageImageSlot{&sky_background_}},
                         {uint32_t(kSkyViewSize[0]), uint32_t(kSkyViewSize[1]), 1}, {8, 8, 1},
                         kSkyViewSize.data());
      timer_->End(cmd);
    }
    timer_->Begin(cmd, "opaque raster");
    // Sky pixels keep distance -1; reversed Z clears depth to 0 (infinitely far).
    opaque_.Draw(cmd, {.colors = {&surface_}, .clear_colors = {std::array<float, 4>{0, 0, 0, -1}},
                       .depth = &depth_, .clear_depth = 0.0f},
                 {atmosphere, frame, sampled(tables_.transmittance()), sampled(tables_.irradiance())},
                 geometry_.opaque_vertices(), geometry_.opaque_indices(), geometry_.opaque_index_count());
    timer_->End(cmd);
    vk::FullBarrier(cmd);
    timer_->Begin(cmd, "composite");
    // No clear: the sky pass and the geometry pass below together write every pixel once.
    composite_sky_.Draw(cmd, {.colors = {&output_}, .clear_colors = {std::nullopt}, .depth = &depth_},
                        {atmosphere, frame, sampled(tables_.transmittance()), sampled(tables_.rayleigh()),
                         sampled(tables_.mie()), sampled(tables_.multiple()), sampled(tables_.irradiance()),
                         sampled(sky_rayleigh_), sampled(sky_mie_), sampled(sky_background_)},
                        fullscreen_vertices_, fullscreen_indices_, 3);
    composite_surface_.Draw(cmd, {.colors = {&output_}, .clear_colors = {std::nullopt}, .depth = &depth_},
                            {atmosphere, frame, sampled(tables_.transmittance()), sampled(tables_.rayleigh()),
                             sampled(tables_.mie()), sampled(tables_.multiple()), sampled(froxels_.rayleigh()),
                             sampled(froxels_.mie()), sampled(froxels_.transmittance()), sampled(surface_)},
                            fullscreen_vertices_, fullscreen_indices_, 3);
    timer_->End(cmd);
    vk::FullBarrier(cmd);
    timer_->Begin(cmd, "transparent raster");
    if (geometry_.transparent_index_count() > 0) {
      transparent_.Draw(cmd, {.colors = {&output_}, .clear_colors = {std::nullopt}, .depth = &depth_},
                        {atmosphere, frame, sampled(tables_.transmittance()), sampled(tables_.irradiance()),
                         sampled(tables_.rayleigh()), sampled(tables_.mie()), sampled(tables_.multiple()),
                         sampled(froxels_.rayleigh()), sampled(froxels_.mie()),
                         sampled(froxels_.transmittance())},
                        geometry_.transparent_vertices(), geometry_.transparent_indices(),
                        geometry_.transparent_index_count());
    }
    timer_->End(cmd);
    vk::FullBarrier(cmd);
  });
  return timer_->Collect();
}

ImageRgbF Renderer::ReadOutput() const { return Read(output_); }
ImageRgbF Renderer::ReadSurface() const { return Read(surface_); }

ImageRgbF Renderer::Read(const vk::Image& image) const {
  return ImageRgbF{options_.width, options_.height, vk::ReadImageFloats(tables_.context(), image)};
}

}  // namespace aerial
