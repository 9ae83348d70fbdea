#pragma once
// One frame, in three steps (shared/design.md, "The pipeline at a glance"):
//   1. froxel pass: the camera-aligned volume of phase-free inscatter and transmittance, and the
//      sky-view table: the same for whole view rays, per direction around the camera;
//   2. opaque raster (lit surface radiance + distance), then the per-pixel composite: phases from
//      each pixel's own ray, aerial perspective from the froxels (or the tables), sky and sun;
//   3. transparent raster, back to front, froxels read per vertex, phases per pixel, blended.
// The same renderer serves `aerial render`, the viewer and the exporters.
#include <memory>
#include <vector>

#include "aerial/image/image.h"
#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/render/frame_uniforms.h"
#include "aerial/render/scene_geometry.h"
#include "aerial/vk/gpu_timer.h"
#include "aerial/vk/graphics_pipeline.h"
#include "froxel/froxel_volume.h"

namespace aerial {

struct RenderOptions {
  int width = 1280;
  int height = 720;
  FroxelGrid froxels;
  AerialMode mode = AerialMode::kFroxel;

  void Validate() const;  // throws aerial::Error for an absurd size
};

class Renderer {
 public:
  // The scene's meshes are uploaded once; its camera and sun may change from frame to frame.
  Renderer(const AtmosphereTables& tables, const Scene& scene, const RenderOptions& options);
  ~Renderer();

  // Renders one frame and waits for it. Returns the GPU time of each pass.
  std::vector<vk::PassTime> Render(const Scene& scene);

  ImageRgbF ReadOutput() const;  // linear radiance of the last frame
  // The opaque pass's target: lit surface radiance before aerial perspective in rgb, distance
  // from the camera in a (negative where no geometry was drawn).
  ImageRgbF ReadSurface() const;
  // The images behind ReadOutput and ReadSurface (GENERAL layout, sampled), for passes that read
  // the frame on the GPU (the viewer's tone map and debug views).
  const vk::Image& output_image() const { return output_; }
  const vk::Image& surface_image() const { return surface_; }
  const AtmosphereTables& tables() const { return tables_; }
  const FroxelVolume& froxels() const { return froxels_; }
  const FrameUniforms& frame_uniforms() const { return frame_uniforms_; }
  const RenderOptions& options() const { return options_; }

 private:
  ImageRgbF Read(const vk::Image& image) const;

  const AtmosphereTables& tables_;
  RenderOptions options_;
  SceneGeometry geometry_;
  FroxelVolume froxels_;
  vk::Buffer frame_buffer_;
  FrameUniforms frame_uniforms_{};
  vk::Image surface_, depth_, output_;
  vk::Image sky_rayleigh_, sky_mie_, sky_background_;
  vk::ComputePipeline sky_view_;
  vk::GraphicsPipeline opaque_, transparent_, composite_sky_, composite_surface_;
  vk::Buffer fullscreen_vertices_, fullscreen_indices_;
  std::unique_ptr<vk::GpuTimer> timer_;
};

}  // namespace aerial
