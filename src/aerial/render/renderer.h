#pragma once
// One frame, recorded into one command buffer (docs/design.md, "The frame"):
//   0. the sun's shadow map of the opaque scene (shadow_map.h), when the sun, the cascades' fit
//      or the terrain it draws changed since it was last drawn;
//   1. compute: the froxel volume of phase-free inscatter and transmittance, and, when the
//      camera's altitude or the sun moved, the sky-view table (the same for whole view rays);
//   2. one raster pass, with no image round trip inside: the opaque meshes and the terrain,
//      nearest first, each fragment lit and seen through the air in the same shader (froxels or
//      tables, phases from the fragment's own ray); then the sky, only where no geometry was
//      drawn (depth test EQUAL against the cleared depth); then the transparent objects, back to
//      front, reading the froxels per vertex, phases per pixel, blended. With shadows, a frame
//      whose view moved draws its opaque geometry in a scope of its own that also writes the sun's
//      visibility, which the frames of a still view then read back (opaque_fragment.glsl).
// The same renderer serves `aerial render`, the viewer and the exporters. Record writes nothing
// the GPU may still be reading: its per-frame buffers have one copy per frame in flight.
#include <memory>
#include <optional>
#include <vector>

#include "aerial/image.h"
#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/render/frame_cache_policy.h"
#include "aerial/render/frame_uniforms.h"
#include "aerial/render/gpu_chunk_selection.h"
#include "aerial/render/recorded_draws.h"
#include "aerial/render/renderer_options.h"
#include "aerial/render/scene_geometry.h"
#include "aerial/render/shadow_map.h"
#include "aerial/render/terrain_chunk_cache.h"
#include "aerial/renderer.h"
#include "aerial/vk/gpu_timer.h"
#include "aerial/vk/graphics_pipeline.h"
#include "aerial/vk/indirect_draws.h"
#include "froxel/froxel_volume.h"

namespace aerial {

// What ReadSurface draws of the lighting: all of it (the sun's part shadowed as in the frame), or
// the sky's part alone.
enum class SurfaceLight { kSunAndSky, kSkyOnly };

// Where an opaque pass takes the sun's visibility from (opaque_fragment.glsl): it looks it up; it
// looks it up and also writes it to the screen's cache; it reads the cache back.
enum class SunVisibilitySource { kLookUp, kLookUpAndCache, kCache };

// The opaque pass's pipelines of one way of reading the froxels (opaque_fragment.glsl), one per
// SunVisibilitySource (the two of the cache with shadows on only).
struct OpaquePipelines {
  vk::GraphicsPipeline look_up;
  std::optional<vk::GraphicsPipeline> look_up_and_cache, cache;
  const vk::GraphicsPipeline& For(SunVisibilitySource source) const;
};

// The mesh passes' pipelines of one shader variant: the opaque pass reading the froxels per pixel
// (or, in the per-pixel modes, the tables), and in froxel mode per vertex on small triangles
// (surface_reads.h); then the transparent objects.
struct MeshPipelines {
  OpaquePipelines per_pixel;
  std::optional<OpaquePipelines> per_vertex;
  vk::GraphicsPipeline transparent;
  // The full-screen pass that applies the opaque surfaces' aerial perspective after them
  // (AerialPerspectiveInFullScreenPass), if they leave it to one.
  std::optional<vk::GraphicsPipeline> composite;
};

class Renderer {
 public:
  // The scene's meshes are uploaded once; its camera and sun may change from frame to frame.
  Renderer(const AtmosphereTables& tables, const Scene& scene, const RendererOptions& options);
  // The level of detail's terrain, every pass.
  Renderer(const AtmosphereTables& tables, const Scene& scene, const RenderOptions& options)
      : Renderer(tables, scene, RendererOptions{options}) {}
  ~Renderer();

  // Records one frame into cmd, with the per-frame resources of slot (< frames_in_flight). The
  // caller makes sure the slot's previous frame has finished (a CommandRing does). complete: build
  // every terrain chunk the frame needs whatever the budget (the first frame always does) and
  // remake a sky-view table made for a nearby altitude, so that the frame is the one
  // `aerial render` makes of the same view.
  void Record(const vk::CommandBuffer& cmd, const Scene& scene, uint32_t slot = 0,
              bool complete = false);
  // The terrain's error bound for the next frames (RenderOptions::terrain_error_px, validated):
  // only the selection uses it, so it may change from frame to frame.
  void SetTerrainErrorPx(double error_px);
  // The render scale of the next frames (RenderOptions::render_scale, validated): only the render
  // size's targets are made again, so a dynamic resolution's steps cost no pipeline builds. No
  // frame in flight may still use the old targets.
  void SetRenderScale(double render_scale);
  // GPU time of each pass of the slot's last frame; call once that frame has finished.
  std::vector<vk::PassTime> PassTimes(uint32_t slot = 0) const;
  // Records one frame, submits it and waits for it. Returns the GPU time of each pass. A one-off
  // frame is complete (Record): each call draws the exact frame of its view, whatever the views
  // before it; a caller that draws a stream of frames as the viewer does passes false.
  std::vector<vk::PassTime> Render(const Scene& scene, bool complete = true);

  // Linear radiance of the last frame at the output size (upscaled when render_scale < 1).
  ImageRgbF ReadOutput() const;
  // The last frame's opaque geometry drawn again at the render size, without aerial perspective:
  // lit surface radiance in rgb, distance from the camera (m) in a, a = -1 where no geometry is.
  // For checks and benchmarks; frames never draw it.
  ImageRgbF ReadSurface(SurfaceLight light = SurfaceLight::kSunAndSky) const;

  // The frame's images at the render size (GENERAL layout, sampled) for passes that read it on
  // the GPU (the viewer's tone map and debug views): radiance, and reversed-Z depth.
  const vk::Image& output_image() const { return output_; }
  const vk::Image& depth_image() const { return depth_; }
  const vk::Buffer& frame_buffer(uint32_t slot) const { return frame_buffers_[slot]; }
  // The ShadowBlock of the slot's frame and the shadow map (shaders/include/shadow.glsl), for
  // passes that look the sun's visibility up.
  const vk::Buffer& shadow_buffer(uint32_t slot) const { return shadow_buffers_[slot]; }
  const ShadowMap& shadow_map() const { return shadow_map_; }
  const ShadowCascades& shadow_cascades() const { return shadow_cascades_; }  // of the last frame
  const AtmosphereTables& tables() const { return tables_; }
  const FroxelVolume& froxels() const { return froxels_; }
  const FrameUniforms& frame_uniforms() const { return frame_uniforms_; }  // of the last frame
  const RendererOptions& options() const { return options_; }
  const FrameInfo& frame_info() const { return frame_info_; }
  // Whether the last frame's mesh passes were the variant for a high sun (MeshPipelinesFor).
  bool mesh_sun_high() const { return mesh_sun_high_used_; }
  // Whether the last frame's sky (its pass per pixel, or the sky-view lattice's correction in
  // froxel mode) was the variant for a high sun (SkySunHighThisFrame).
  bool sky_sun_high() const { return sky_sun_high_used_; }

 private:
  terrain::LodView FrameLodView(const Scene& scene) const;
  void SelectTerrain(const Scene& scene, bool complete, uint32_t slot);
  // The GPU's selection: builds what the last ones read back asked for (the frame's and the
  // shadow casters'; a complete frame: all the view needs, found by the CPU's rule), passes the
  // chunk slots' changes to the trees (ApplyTerrainSlotChanges), and decides
  // whether this frame selects again (RecordTerrainSelection) or draws what the last one chose.
  void PrepareGpuTerrainSelection(const terrain::LodView& view, bool complete, uint32_t slot);
  void RecordTerrainSelection(const vk::CommandBuffer& cmd, uint32_t slot);
  void ApplyTerrainSlotChanges();
  // Within which distance a chunk reads the froxels per pixel (ChooseFroxelReads's rule).
  double PerPixelReadsWithinM(const terrain::ChunkInfo& info) const;
  void RecordShadowMap(const vk::CommandBuffer& cmd, const Scene& scene, uint32_t slot, bool exact);
  // With the GPU's caster selection: whether the tile of `cascade` is redrawn, its casters selected
  // again (gpu_shadow_casters.h); moved: its window moved.
  bool RecordGpuCasters(const vk::CommandBuffer& cmd, int cascade, const terrain::LodView& lod_view, uint32_t slot,
                        bool moved, bool exact);
  // Whether this frame remakes the sky-view table (stale, or a band of its lattice was remade); if
  // so, its key becomes this frame's.
  bool SkyViewStale(bool exact, bool lattice_remade);
  void RecordSkyViewCorrection(const vk::CommandBuffer& cmd, const vk::Buffer& frame,
                               const std::array<bool, kSkyViewLatticeBands>& remake);
  void RecordSkyView(const vk::CommandBuffer& cmd, const vk::Buffer& frame);
  // The mesh pipelines of this frame's variant (renderer.cpp says when it is the high sun's).
  const MeshPipelines& MeshPipelinesFor(const Scene& scene);
  bool SkySunHighThisFrame() const;
  const vk::GraphicsPipeline& SkyPipelineFor();
  const vk::ComputePipeline& SkyViewCorrectionPipelineFor();
  std::vector<vk::Slot> MeshSlots(uint32_t slot) const;
  void ChooseFroxelReads(const Camera& camera);
  // The draw functions return what they recorded (FrameInfo::draws, ::draw_binds).
  // The opaque draws' commands go to `commands`, started for all of them (BeginOpaqueCommands).
  void BeginOpaqueCommands(vk::IndirectDraws& commands) const;
  RecordedDraws DrawOpaqueRun(const vk::CommandBuffer& cmd, const vk::GraphicsPipeline& pipeline,
                              const std::vector<vk::Slot>& slots, std::optional<bool> pixel_reads,
                              vk::IndirectDraws& commands) const;
  RecordedDraws DrawOpaque(const vk::CommandBuffer& cmd, const MeshPipelines& pipelines,
                           SunVisibilitySource source, const std::vector<vk::Slot>& slots,
                           vk::IndirectDraws& commands) const;
  RecordedDraws DrawComposite(const vk::CommandBuffer& cmd, uint32_t slot, const vk::GraphicsPipeline& composite,
                              std::vector<vk::Slot> mesh_slots) const;
  RecordedDraws DrawSkyAndTransparent(const vk::CommandBuffer& cmd, uint32_t slot, const vk::GraphicsPipeline& sky,
                                      const vk::GraphicsPipeline& transparent,
                                      const std::vector<vk::Slot>& mesh_slots) const;

  const AtmosphereTables& tables_;
  RendererOptions options_;
  SceneGeometry geometry_;
  std::unique_ptr<TerrainChunkCache> terrain_;  // null without a terrain or with the fixed mesh
  // With TerrainSelector::kGpu: the selection, which writes the terrain's draws (terrain_chunks_
  // stays empty), whether this frame records one, and the last selection whose feedback was read.
  std::unique_ptr<GpuChunkSelection> gpu_terrain_;
  std::unique_ptr<GpuShadowCasters> gpu_casters_;  // with it and the shadows: the tiles' casters
  bool gpu_terrain_due_ = false;
  GpuChunkSelection::Feedback gpu_terrain_feedback_;
  bool terrain_feedback_pending_ = false;  // the selection that draws may still ask for chunks
  // Counts the changes of the terrain chunks drawn: equal counts, the same chunks.
  uint64_t terrain_changes_ = 0;
  // Front to back within each of two runs: the chunks that read the froxels per pixel first
  // (surface_reads.h), terrain_per_pixel_ of them, then those that read them per vertex.
  std::vector<terrain::SelectedChunk> terrain_chunks_;
  size_t terrain_per_pixel_ = 0;
  std::vector<char> mesh_reads_per_pixel_;  // per SceneGeometry::opaque_draws()
  // What the selection of terrain_chunks_ left out as hidden, and drew in place of finer chunks not
  // built yet (-1 before the first selection); the frames that keep it report the same.
  int terrain_hidden_ = 0, terrain_deferred_ = -1;
  std::optional<terrain::LodView> terrain_selected_for_;  // the view terrain_chunks_ were selected for
  FrameInfo frame_info_;
  uint64_t frames_recorded_ = 0;
  uint32_t last_slot_ = 0;
  FroxelVolume froxels_;
  std::vector<vk::Buffer> frame_buffers_;
  std::vector<std::unique_ptr<vk::GpuTimer>> timers_;
  // Per frame slot, the indirect draws' commands of the opaque pass and of the shadow tiles.
  std::vector<vk::IndirectDraws> opaque_commands_, shadow_commands_;
  FrameUniforms frame_uniforms_{};
  vk::Image depth_, output_;
  // The sun's visibility of the front-most opaque surface at each pixel, as the last frame that
  // looked it up in the shadow map drew it (opaque_fragment.glsl), and what that frame showed.
  vk::Image sun_visibility_;
  std::optional<SunVisibilityKey> sun_visibility_key_;
  // With the aerial perspective applied in a full-screen pass: the opaque surfaces' radiance and
  // distance, which that pass reads (aerial_composite.frag); else one texel.
  vk::Image surface_radiance_;
  vk::Image sky_rayleigh_, sky_mie_, sky_background_;
  // The sky inscatter correction at the sky-view table's lattice nodes.
  vk::Image sky_rayleigh_correction_, sky_mie_correction_;
  std::optional<SkyViewKey> sky_view_key_;  // what the sky-view table was made for
  SkyViewLatticeKeys sky_view_lattice_keys_;  // and each band of its correction lattice
  std::optional<FrameUniforms> froxels_key_;  // the frame the froxel volume was built for
  ShadowMap shadow_map_;
  std::vector<vk::Buffer> shadow_buffers_;
  CasterBounds casters_;
  ShadowCascades shadow_cascades_{};  // of the last frame
  std::optional<ShadowKey> shadow_key_;  // what the shadow map's tiles show
  // The view did not move since the last frame, whose shadow terrain selection lacked no chunk:
  // this frame's would be the same.
  bool still_view_ = false;
  bool shadow_selection_whole_ = false;
  vk::ComputePipeline sky_view_correction_, sky_view_;
  double scene_radius_m_;  // how far from the scene's origin a surface may lie
  MeshPipelines mesh_;
  // The marched per-pixel path's variant for a high sun (MeshPipelinesFor), made at its first use,
  // and whether the last frame drew with it.
  std::optional<MeshPipelines> mesh_sun_high_;
  bool mesh_sun_high_used_ = false;
  vk::GraphicsPipeline sky_, surface_;
  // Froxel mode: the sun's disc added over the sky around it (sun_disc.frag).
  std::optional<vk::GraphicsPipeline> sun_disc_;
  // The same for the sky (SkyPipelineFor) and the sky-view lattice's correction
  // (SkyViewCorrectionPipelineFor); whether the last frame's sky took it.
  std::optional<vk::GraphicsPipeline> sky_sun_high_;
  std::optional<vk::ComputePipeline> sky_view_correction_sun_high_;
  bool sky_sun_high_used_ = false;
};

}  // namespace aerial
