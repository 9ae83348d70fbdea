#include "aerial/render/shadow_map.h"

#include "aerial/render/shadow_uniforms.h"
#include "aerial/shader_abi/frame_geometry.h"
#include "aerial/terrain/terrain_chunk.h"

namespace aerial {
namespace {

constexpr ::vk::Format kShadowFormat = ::vk::Format::eD32Sfloat;

uint32_t AtlasTexels(bool enabled) { return enabled ? uint32_t(kShadowTileTexels * kShadowAtlasTilesPerRow) : 1u; }

vk::ImageCreateInfo AtlasImage(bool enabled) {
  return {.extent = {AtlasTexels(enabled), AtlasTexels(enabled), 1},
          .format = kShadowFormat,
          .usage = ::vk::ImageUsageFlagBits::eDepthStencilAttachment | ::vk::ImageUsageFlagBits::eSampled |
                   ::vk::ImageUsageFlagBits::eTransferSrc};
}

struct CascadeConstants {
  std::array<float, 16> clip_from_relative;
  std::array<float, 4> camera_scene_position;
};

// Along a ray from the sun, the first surface of the terrain (a heightfield) it meets faces the sun,
// so the terrain's triangles turned away from it never hold a texel's depth: they are culled,
// sparing the rasterizer the far sides of the hills, many of which a low sun's rays cross. The
// tile's axes (right, up, toward the sun) are right-handed, so a sun-facing triangle,
// counter-clockwise seen from above, is counter-clockwise in clip x and y, and so clockwise by
// Vulkan's rule in framebuffer coordinates: "back" to the pipeline's counter-clockwise front faces.
// The scene's meshes may be open or double-sided, so they keep both sides.
constexpr ::vk::CullModeFlags kTerrainTurnedAwayFromTheSun = ::vk::CullModeFlagBits::eFront;

vk::GraphicsPipelineCreateInfo DepthPipeline() {
  return {.vertex_shader = "frame/shadow_depth.vert",
          .push_constant_bytes = sizeof(CascadeConstants),
          .vertex_stride = sizeof(Vertex),
          .attributes = {{::vk::Format::eR32G32B32Sfloat, offsetof(Vertex, position)}},
          .depth_format = kShadowFormat,
          .dynamic_cull_mode = true};
}

}  // namespace

ShadowMap::ShadowMap(const vk::Context& context, bool enabled)
    : atlas_(context, AtlasImage(enabled)),
      sampler_(vk::CreateShadowMapSampler(context)),
      depth_(context, DepthPipeline()) {
  context.Submit([&](const auto& cmd) { atlas_.InitializeLayout(cmd); });
}

uint64_t ShadowMap::MemoryBytes(bool enabled) { return uint64_t(AtlasTexels(enabled)) * AtlasTexels(enabled) * 4; }

RecordedDraws ShadowMap::Record(const vk::CommandBuffer& cmd, const ShadowCascades& cascades,
                                const std::array<std::optional<TileTexels>, kShadowCascades>& redraw,
                                const glm::dvec3& camera_position, const SceneGeometry& geometry,
                                const TerrainChunkCache* terrain, const ShadowTerrain& chunks,
                                const GpuShadowCasters* gpu_casters, vk::IndirectDraws& commands) const {
  // One scope for all tiles (each scope costs a pass over the whole atlas on a CPU rasterizer):
  // cleared whole when every tile is redrawn whole for sure, else loaded with the redrawn texels
  // cleared.
  const TileTexels whole = WholeTile(kShadowTileTexels);
  auto if_changed = [&](int i) { return gpu_casters && gpu_casters->IfChanged(i); };
  bool all = true;
  for (int i = 0; i < kShadowCascades; ++i) all = all && redraw[i] == whole && !if_changed(i);
  size_t chunk_count = 0;
  for (int i = 0; i < kShadowCascades; ++i)
    if (redraw[i]) chunk_count += chunks[i].size();
  commands.Begin(chunk_count);
  vk::Rendering rendering(cmd, {.depth = &atlas_, .clear_depth = all ? std::optional(0.0f) : std::nullopt});
  const ::vk::Extent2D tile{uint32_t(kShadowTileTexels), uint32_t(kShadowTileTexels)};
  RecordedDraws recorded;
  for (int i = 0; i < kShadowCascades; ++i) {
    if (!redraw[i] || redraw[i]->Empty()) continue;
    const glm::ivec2 corner((i % kShadowAtlasTilesPerRow) * kShadowTileTexels,
                            (i / kShadowAtlasTilesPerRow) * kShadowTileTexels);
    const glm::ivec2 from = corner + redraw[i]->min, size = redraw[i]->max - redraw[i]->min;
    const ::vk::Rect2D texels{{from.x, from.y}, {uint32_t(size.x), uint32_t(size.y)}};
    // The clear and the draws, where the GPU decides, only if the casters it selected changed.
    if (if_changed(i)) gpu_casters->BeginIfChanged(cmd, i);
    if (!all) vk::ClearDepth(cmd, texels, 0.0f);
    vk::SetViewport(cmd, tile, {corner.x, corner.y});
    vk::SetScissor(cmd, texels);
    CascadeConstants constants{
        ToColumnMajorFloats(ClipFromRelative(cascades[i], camera_position)),
        {float(camera_position.x), float(camera_position.y), float(camera_position.z), 0.0f}};
    depth_.Bind(cmd, {}, &constants);
    ++recorded.binds;
    if (geometry.opaque_index_count() > 0) {
      vk::SetCullMode(cmd, ::vk::CullModeFlagBits::eNone);
      vk::BindMesh(cmd, geometry.opaque_vertices(), geometry.opaque_indices());
      vk::DrawIndexed(cmd, geometry.opaque_index_count());
      ++recorded.draws;
    }
    const bool gpu_selected = gpu_casters && GpuShadowCasters::Selects(i);
    if (terrain && (gpu_selected || !chunks[i].empty())) {
      vk::SetCullMode(cmd, kTerrainTurnedAwayFromTheSun);
      vk::BindMesh(cmd, terrain->vertices(), terrain->indices());
      if (gpu_selected) {
        recorded.draws += gpu_casters->Draw(cmd, i);
      } else {
        for (const terrain::SelectedChunk& chunk : chunks[i]) {
          terrain::IndexRange range = terrain::ChunkIndexRange(chunk.skirts);
          commands.Add(range.count, range.first, terrain->VertexOffset(chunk.id), 0);
        }
        recorded.draws += commands.Draw(cmd);
      }
    }
    if (if_changed(i)) cmd.endConditionalRenderingEXT();
  }
  return recorded;
}

}  // namespace aerial
