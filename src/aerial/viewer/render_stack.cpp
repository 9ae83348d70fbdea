#include "aerial/viewer/render_stack.h"

#include "aerial/api/impl.h"

namespace aerial::viewer {

bool SameRenderOptions(const RendererOptions& a, const RendererOptions& b) {
  return a.width == b.width && a.height == b.height && a.mode == b.mode && a.terrain == b.terrain &&
         a.frames_in_flight == b.frames_in_flight && a.shadows == b.shadows &&
         a.froxels.width == b.froxels.width && a.froxels.height == b.froxels.height &&
         a.froxels.depth == b.froxels.depth && a.froxels.far_m == b.froxels.far_m;
}

void RenderStack::Install(std::unique_ptr<Tables> tables, const RendererOptions& options) {
  Entry& entry = entries_[tables->options().variant];
  if (entry.renderer) before_rebuild_();
  entry.renderer.reset();  // it refers to the old tables
  entry.tables = std::move(tables);
  entry.renderer = std::make_unique<SceneRenderer>(MakeSceneRenderer(*entry.tables, scene_, options));
}

SceneRenderer* RenderStack::Get(LutVariant variant, const RendererOptions& options) {
  auto it = entries_.find(variant);
  if (it == entries_.end()) return nullptr;
  Entry& entry = it->second;
  if (!SameRenderOptions(ImplOf(*entry.renderer).renderer.options(), options)) {
    before_rebuild_();
    entry.renderer.reset();
    entry.renderer = std::make_unique<SceneRenderer>(MakeSceneRenderer(*entry.tables, scene_, options));
  }
  if (entry.renderer->options().render_scale != options.render_scale) {
    before_rebuild_();  // the frames in flight use the targets of the old scale
    entry.renderer->SetRenderScale(options.render_scale);
  }
  entry.renderer->SetTerrainErrorPx(options.terrain_error_px);
  return entry.renderer.get();
}

const Tables* RenderStack::tables(LutVariant variant) const {
  auto it = entries_.find(variant);
  return it == entries_.end() ? nullptr : it->second.tables.get();
}

}  // namespace aerial::viewer
