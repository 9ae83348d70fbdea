#pragma once
// aerial's whole frame of a Scene (aerial/scene.h): the built-in terrain with a level of detail
// that follows the camera, the scene's meshes, the sun's shadow map, the froxel volume, the sky
// and the transparent objects, recorded into one command buffer. It is what `aerial render`, the
// viewer and the exporters draw; a renderer with its own geometry uses Froxels and the GLSL
// contract instead (aerial/froxels.h).
#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan_core.h>

#include "aerial/device.h"
#include "aerial/froxel_grid.h"
#include "aerial/image.h"
#include "aerial/scene.h"
#include "aerial/tables.h"

namespace aerial {

// Where the aerial perspective comes from:
//  - kFroxel: the froxel volume (the default);
//  - kPerPixel: marched along each pixel's ray through the tables, the reference the froxels are
//    measured against;
//  - kTableDifference: per pixel, S(x) - T S(p) from two 4D table reads and no march, as Bruneton
//    2017's demo renders it (docs/accuracy.md, "Radiance to a point"), what a user would otherwise pick.
enum class AerialMode { kFroxel, kPerPixel, kTableDifference };

// The terrain's default screen-space error bound (lod_selection.h), in pixels at 720 rows or
// more: see docs/design.md, "Terrain".
inline constexpr double kDefaultTerrainErrorPx = 4.0;

struct RenderOptions {
  int width = 1280;   // the output image
  int height = 720;
  // The frame is rasterized at render_scale times the output size, then upscaled (bilinear).
  // The terrain's level of detail follows it: terrain_error_px is in the rasterized frame's pixels.
  double render_scale = 1.0;
  FroxelGrid froxels;
  AerialMode mode = AerialMode::kFroxel;
  double terrain_error_px = kDefaultTerrainErrorPx;
  // Leave out terrain chunks that nearer ones hide (terrain/screen_horizon.h): the image is the
  // same either way; off only to measure what it saves.
  bool terrain_occlusion_culling = true;
  // CPU time a frame may spend building terrain chunks (ms); until they are built their parents
  // are drawn. 0: every chunk the frame needs is built first (one-off renders, tests).
  double terrain_build_budget_ms = 0.0;
  // Copies of the per-frame resources: frames recorded before the previous ones finished.
  uint32_t frames_in_flight = 1;
  // The sun's shadow map (shadow_map.h) on surfaces; off: no shadow map, and the frame of before.
  bool shadows = true;

  void Validate() const;  // throws aerial::Error naming the field
  int render_width() const;
  int render_height() const;
};

// The memory a Renderer and one ReadOutput() take, by what sizes it, known before allocating.
struct FrameMemory {
  uint64_t targets = 0;   // radiance and depth at the render size, the sky-view tables
  uint64_t readback = 0;  // ReadOutput's copies (read back, upscaled) and the encoded image
  uint64_t froxels = 0;   // the froxel volume
  uint64_t terrain = 0;   // the terrain chunk slots, and the buffers that select them on a GPU device
  uint64_t shadows = 0;   // the shadow map's depth atlas (--shadows on)
};
FrameMemory EstimateFrameMemory(const RenderOptions& options);

// What the last recorded frame did besides drawing.
struct FrameInfo {
  size_t chunks = 0, triangles = 0;  // terrain drawn
  int deferred = 0;  // terrain chunks drawn in place of finer ones not built yet
  int hidden = 0;    // terrain chunks left out because nearer ones hide them
  int built = 0;     // terrain chunks built for this frame
  // The terrain's chunks were selected for this frame: its camera, render size or level-of-detail
  // bound differs from the last frame's (a frame that differs only in its sun keeps them).
  bool terrain_selected = false;
  bool sky_view_updated = false;  // the sky-view table was remade (the camera's r or mu_s moved)
  bool froxels_updated = false;   // the froxel volume was rebuilt (the camera or the sun moved)
  bool shadow_map_updated = false;  // the shadow map was redrawn (shadow_map.h), in part or whole
  // Of its kShadowCascades tiles, one per cascade, those redrawn whole; with the terrain's casters
  // selected on the GPU, those whose casters it selected again, which it redraws only if they changed.
  int shadow_tiles_redrawn = 0;
  // Tiles redrawn in part: only the texels where the terrain chunks they draw changed.
  int shadow_tile_regions_redrawn = 0;
  // Draw calls and pipeline binds (each with its descriptors pushed) that the frame's raster passes
  // recorded: the shadow tiles, the opaque pass, the sky and the transparent objects. The meshes and
  // the terrain's chunks are indirect draws, a few per pass, so they do not grow with the scene.
  int draws = 0, draw_binds = 0;
  // The opaque pass read the sun visibility that an earlier frame of the same view looked up
  // (opaque_fragment.glsl) instead of looking it up.
  bool sun_visibility_cached = false;
  // Nothing was left for later (terrain chunks of the frame or of the shadow map deferred for the
  // build budget, shadow tiles still drawn for an earlier sun): the next frame of the same camera,
  // sun and options is this frame's image.
  bool settled = false;
};

class SceneRenderer {
 public:
  // The scene's meshes are uploaded once; its camera and sun may change from frame to frame.
  // Throws aerial::Error for invalid options, naming the option.
  SceneRenderer(const Tables& tables, const Scene& scene, const RenderOptions& options);
  ~SceneRenderer();
  SceneRenderer(SceneRenderer&&) noexcept;
  SceneRenderer& operator=(SceneRenderer&&) noexcept;

  // Records one frame of the scene's view into the caller's command buffer (outside a render
  // pass), with the per-frame resources of slot (< frames_in_flight): the caller makes sure the
  // slot's previous frame has finished. complete: build every terrain chunk the frame needs
  // whatever the time budget, so that the frame is the one Render makes of the same view.
  void Record(VkCommandBuffer command_buffer, const Scene& scene, uint32_t slot = 0, bool complete = false);
  // Records one frame, submits it and waits for it; the GPU time of each pass.
  std::vector<PassTime> Render(const Scene& scene, bool complete = true);
  // The GPU time of each pass of the slot's last frame, once that frame has finished.
  std::vector<PassTime> PassTimes(uint32_t slot = 0) const;
  // Linear radiance of the last frame at the output size (upscaled when render_scale < 1), once
  // it has finished.
  ImageRgbF ReadOutput() const;
  // The terrain's error bound for the next frames (RenderOptions::terrain_error_px, validated):
  // only the chunk selection uses it, so it may change from frame to frame without a rebuild.
  void SetTerrainErrorPx(double error_px);
  // The render scale of the next frames (RenderOptions::render_scale, validated): the render size's
  // images (output(), depth()) are made again, nothing else, so a dynamic resolution may step
  // without a rebuild. The caller waits first for the frames in flight that use the old ones.
  void SetRenderScale(double render_scale);

  // What the caller's own passes may read of the last frame (a viewer's tone map and debug
  // views): the radiance and the reversed-Z depth at the render size, the FrameBlock of the
  // slot's frame, and the froxel volume it was shaded with.
  SampledImage output() const;
  SampledImage depth() const;
  UniformBlock frame_block(uint32_t slot = 0) const;
  SampledImage froxel_rayleigh() const;
  SampledImage froxel_mie() const;
  SampledImage froxel_transmittance() const;

  const Tables& tables() const;
  const FrameInfo& frame_info() const;
  const RenderOptions& options() const;

  struct Impl;  // aerial's side (src/aerial/api/impl.h)

 private:
  friend struct ImplAccess;  // aerial's own code (src/aerial/api/impl.h)
  explicit SceneRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace aerial
