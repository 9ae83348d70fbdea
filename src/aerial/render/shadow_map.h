#pragma once
// The sun's shadow map of the opaque scene (the terrain and the opaque meshes; transparent ones
// cast no shadow): one depth atlas of kShadowCascades square tiles (2x2), each the depth of the
// casters nearest the sun through its cascade's orthographic projection (shadow_cascades.h),
// reversed like the camera's depth (1 nearest the sun, cleared to 0, GREATER test). Read by
// shaders/include/shadow.glsl with a comparing sampler (PCF) and the per-frame ShadowBlock
// (shadow_uniforms.h).
//
// The renderer records it into the frame's command buffer before the froxels and the raster
// pass, tile by tile, and only the tiles whose content changed (Renderer's shadow key): the sun,
// the cascade's window (shadow_cascades.h: kept while its slice fits) or the terrain it draws as
// the tile resolves it (shadow_terrain.h), the last only where those chunks lie
// (shadow_tile_region.h). A still camera redraws nothing, a moving one a tile now and then.
#include <cstdint>

#include "aerial/render/gpu_shadow_casters.h"
#include "aerial/render/recorded_draws.h"
#include "aerial/render/scene_geometry.h"
#include "aerial/render/shadow_cascades.h"
#include "aerial/render/shadow_terrain.h"
#include "aerial/render/shadow_tile_region.h"
#include "aerial/render/terrain_chunk_cache.h"
#include "aerial/vk/graphics_pipeline.h"
#include "aerial/vk/indirect_draws.h"

namespace aerial {

// Texels per side of one cascade's tile: 1024 puts the first cascade's texel at 11 cm (the 60 m
// slice of a 50-degree view at 16:9) and the last one's at 170 m, enough for a ridge's shadow
// 80 km away, at 16 MiB for the atlas.
inline constexpr int kShadowTileTexels = 1024;

class ShadowMap {
 public:
  // enabled = false: a 1x1 placeholder that the frame's shaders bind but never read.
  ShadowMap(const vk::Context& context, bool enabled);

  // The atlas' bytes (the placeholder's when not enabled).
  static uint64_t MemoryBytes(bool enabled);

  // Clears the texels of each tile in `redraw` (nullopt: kept; the whole tile, or the region where
  // its casters changed: shadow_tile_region.h) and draws its casters there: the scene's opaque
  // meshes (both faces: a mesh open to the sun still shades what is behind it) and the terrain
  // chunks that reach the texels: `chunks`, one indirect draw per tile from `commands` (the frame
  // slot's), or, with gpu_casters for the tiles it selects (GpuShadowCasters::Selects), the
  // draws of the casters that the GPU selected. Other texels keep what they hold. Returns what it
  // recorded.
  RecordedDraws Record(const vk::CommandBuffer& cmd, const ShadowCascades& cascades,
                       const std::array<std::optional<TileTexels>, kShadowCascades>& redraw,
                       const glm::dvec3& camera_position, const SceneGeometry& geometry,
                       const TerrainChunkCache* terrain, const ShadowTerrain& chunks,
                       const GpuShadowCasters* gpu_casters, vk::IndirectDraws& commands) const;

  const vk::Image& atlas() const { return atlas_; }
  // The atlas with its comparing sampler, as the shaders bind it (shadow_map in shadow.glsl).
  vk::SampledImageSlot slot() const { return {&atlas_, *sampler_}; }

 private:
  vk::Image atlas_;
  ::vk::raii::Sampler sampler_;
  vk::GraphicsPipeline depth_;
};

}  // namespace aerial
