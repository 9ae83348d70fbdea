#include "aerial/viewer/display_passes.h"

#include "aerial/vk/present_target.h"

namespace aerial::viewer {
namespace {

using vk::kSampled;
using vk::kUniform;

// Every push block starts with the target's size in pixels (the shaders' uv = gl_FragCoord / size).
struct ToneMapPush {
  float target_size[2];
  float exposure;
  float padding;  // a vec3 starts at a multiple of 16 bytes
  float white_balance[3];
};

struct TermPush {
  float target_size[2];
  int32_t term;
  int32_t from_froxels;
  float exposure;
};

struct SlicePush {
  float target_size[2];
  int32_t slice;
  float exposure;
};

struct DifferencePush {
  float target_size[2];
  float full_scale;
};

// Constant 0 is frame.glsl's aerial mode (unused here), 1 display.glsl's kTargetEncodesSrgb,
// 2 present.frag's kResampled.
vk::GraphicsPipelineCreateInfo FullScreen(::vk::RenderPass render_pass, ::vk::Format format,
                                          const std::string& fragment,
                                          vk::SlotLayout slots, uint32_t push_bytes, bool resampled = false) {
  return {.vertex_shader = "frame/fullscreen.vert",
          .fragment_shader = fragment,
          .slots = std::move(slots),
          .push_constant_bytes = push_bytes,
          .render_pass = render_pass,
          .depth_write = false,
          .specialization = {0, vk::EncodesSrgb(format) ? 1 : 0, resampled ? 1 : 0}};
}

}  // namespace

DisplayPasses::DisplayPasses(const vk::Context& context, ::vk::RenderPass render_pass, ::vk::Format format)
    : linear_(vk::CreateLinearClampSampler(context)),
      nearest_(vk::CreateNearestClampSampler(context)),
      tone_map_(context, FullScreen(render_pass, format, "view/present.frag", {{"radiance_image", kSampled}},
                                     sizeof(ToneMapPush))),
      tone_map_resampled_(context, FullScreen(render_pass, format, "view/present.frag",
                                              {{"radiance_image", kSampled}}, sizeof(ToneMapPush), true)),
      term_(context, FullScreen(render_pass, format, "view/inscatter.frag",
                                {{"AtmosphereBlock", kUniform},
                                 {"FrameBlock", kUniform},
                                 {"transmittance_texture", kSampled},
                                 {"rayleigh_texture", kSampled},
                                 {"mie_texture", kSampled},
                                 {"multiple_texture", kSampled},
                                 {"multiple_density_texture", kSampled},
                                 {"rayleigh_froxels", kSampled},
                                 {"mie_froxels", kSampled},
                                 {"transmittance_froxels", kSampled},
                                 {"depth_texture", kSampled}},
                                sizeof(TermPush))),
      froxel_slice_(context, FullScreen(render_pass, format, "view/froxel_slice.frag",
                                        {{"rayleigh_froxels", kSampled},
                                         {"mie_froxels", kSampled},
                                         {"transmittance_froxels", kSampled}},
                                        sizeof(SlicePush))),
      difference_(context, FullScreen(render_pass, format, "view/difference.frag",
                                      {{"radiance_4d", kSampled}, {"radiance_3d", kSampled}},
                                      sizeof(DifferencePush))) {}

void DisplayPasses::RecordToneMap(const vk::CommandBuffer& cmd, ::vk::Extent2D extent,
                                  const SampledImage& radiance, float exposure,
                                  const std::array<float, 3>& white_balance) const {
  ToneMapPush push{{float(extent.width), float(extent.height)}, exposure, 0.0f,
                   {white_balance[0], white_balance[1], white_balance[2]}};
  const bool same_size = radiance.extent.width == extent.width && radiance.extent.height == extent.height;
  (same_size ? tone_map_ : tone_map_resampled_).Bind(cmd, {Linear(radiance)}, &push);
  vk::DrawGeneratedTriangle(cmd);
}

void DisplayPasses::RecordTerm(const vk::CommandBuffer& cmd, ::vk::Extent2D extent,
                               const SceneRenderer& renderer, uint32_t slot, Term term,
                               float exposure) const {
  const Tables& tables = renderer.tables();
  TermPush push{{float(extent.width), float(extent.height)}, int32_t(term),
                renderer.options().mode == AerialMode::kFroxel ? 1 : 0, exposure};
  term_.Bind(cmd,
             {vk::UniformBlockSlot{tables.atmosphere_block().buffer},
              vk::UniformBlockSlot{renderer.frame_block(slot).buffer}, Linear(tables.transmittance()),
              Linear(tables.rayleigh()), Linear(tables.mie()), Linear(tables.multiple()),
              Linear(tables.multiple_density()), Linear(renderer.froxel_rayleigh()), Linear(renderer.froxel_mie()),
              Linear(renderer.froxel_transmittance()), vk::SampledViewSlot{renderer.depth().view, *nearest_}},
             &push);
  vk::DrawGeneratedTriangle(cmd);
}

void DisplayPasses::RecordFroxelSlice(const vk::CommandBuffer& cmd, ::vk::Extent2D extent,
                                      const SceneRenderer& renderer, int slice, float exposure) const {
  SlicePush push{{float(extent.width), float(extent.height)}, slice, exposure};
  froxel_slice_.Bind(cmd,
                     {Linear(renderer.froxel_rayleigh()), Linear(renderer.froxel_mie()),
                      Linear(renderer.froxel_transmittance())},
                     &push);
  vk::DrawGeneratedTriangle(cmd);
}

void DisplayPasses::RecordDifference(const vk::CommandBuffer& cmd, ::vk::Extent2D extent,
                                     const SampledImage& radiance_4d, const SampledImage& radiance_3d,
                                     float full_scale) const {
  DifferencePush push{{float(extent.width), float(extent.height)}, full_scale};
  difference_.Bind(cmd, {Linear(radiance_4d), Linear(radiance_3d)}, &push);
  vk::DrawGeneratedTriangle(cmd);
}

}  // namespace aerial::viewer
