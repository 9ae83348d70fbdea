#pragma once
// The table sets and renderers the viewer draws with: one per table variant, the current one and,
// for the 3D-vs-4D view, the other. Every renderer is aerial's SceneRenderer (aerial/renderer.h),
// rebuilt when its tables or its options change: the size (a resize), the froxel grid, the
// aerial mode and the shadows, which are specialization constants of its pipelines (and the
// shadows its shadow map); the render scale (its targets alone) and the terrain's error bound are
// passed on without a rebuild. Frames in flight may still use a renderer, so the stack calls its owner's
// before_rebuild (which waits for them) first.
#include <functional>
#include <map>
#include <memory>

#include "aerial/render/renderer_options.h"

namespace aerial::viewer {

class RenderStack {
 public:
  // scene: its meshes go to every renderer; it must outlive the stack (which may be moved).
  // before_rebuild: called before a renderer is destroyed.
  RenderStack(const Scene& scene, std::function<void()> before_rebuild)
      : scene_(scene), before_rebuild_(std::move(before_rebuild)) {}

  // Replaces the tables of their variant, and that variant's renderer.
  void Install(std::unique_ptr<Tables> tables, const RendererOptions& options);
  // The variant's renderer, rebuilt first if its options differ; null if the variant has no
  // tables yet. Its tables may be for an older atmosphere while new ones are being made: check
  // renderer->tables().atmosphere() where that matters.
  SceneRenderer* Get(LutVariant variant, const RendererOptions& options);
  // The variant's tables, whatever atmosphere they were made for; null if none.
  const Tables* tables(LutVariant variant) const;

 private:
  struct Entry {
    std::unique_ptr<Tables> tables;
    std::unique_ptr<SceneRenderer> renderer;
  };
  const Scene& scene_;
  std::function<void()> before_rebuild_;
  std::map<LutVariant, Entry> entries_;
};

bool SameRenderOptions(const RendererOptions& a, const RendererOptions& b);

}  // namespace aerial::viewer
