// The scene's own surface (aerial/scene_surface.h) at the renderer's depth, over every
// opaque pixel of the presets' views: the bench's reference lights surfaces where SurfaceAtDepth
// finds them, so it must find them wherever the renderer draws the terrain or a landmark. When
// written: none missing in the four views from the ground (landmarks found as meshes on 102
// pixels at noon, the terrain within 0.70 of its tolerance), 1 of 16,563 at high altitude (at
// 1.01 of it, 84 km away).
#include <gtest/gtest.h>

#include <cmath>

#include "aerial/render/renderer.h"
#include "aerial/scene.h"
#include "aerial/terrain/scene_surface.h"
#include "aerial/validation/image_metrics.h"
#include "aerial/validation/reference_sampling.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

class SceneSurfaceRender : public GpuTest {};

// The landmarks' stone albedo (default_scene.cpp), which no terrain material has.
bool IsLandmarkStone(const Spectrum& albedo) {
  const double stone[3] = {0.42, 0.39, 0.34};
  for (int c = 0; c < 3; ++c)
    if (std::abs(albedo[c] - stone[c]) > 1e-6) return false;
  return true;
}

TEST_F(SceneSurfaceRender, FoundAtTheRenderersDepthAtAlmostEveryOpaquePixel) {
  const AtmosphereTables& tables = SmallTables();
  const double R = tables.atmosphere().bottom_radius_m;
  for (const std::string& preset : PresetNames()) {
    SCOPED_TRACE(preset);
    Scene scene = validation::OpaqueScene(BuildPreset(preset, R));
    Renderer renderer(tables, scene, {.width = 320, .height = 180});
    renderer.Render(scene);
    ImageRgbF surface = renderer.ReadSurface();
    double tolerance = TerrainTolerancePerM(scene.camera, surface.height, renderer.options().terrain_error_px);
    int opaque = 0, missing = 0, landmark = 0;
    for (int y = 0; y < surface.height; ++y) {
      for (int x = 0; x < surface.width; ++x) {
        if (validation::IsSky(surface, x, y)) continue;
        ++opaque;
        auto found = SurfaceAtDepth(scene, R, validation::PixelRay(renderer.frame_uniforms(), x, y),
                                           surface.pixel(x, y)[3], tolerance);
        if (!found) {
          ++missing;
        } else if (IsLandmarkStone(found->albedo)) {
          ++landmark;
        }
      }
    }
    EXPECT_LE(missing, opaque / 10000) << opaque << " opaque pixels";
    if (preset == "noon") {
      EXPECT_GT(landmark, 50) << "the landmarks, found by the ray cast";
    }
  }
}

}  // namespace
}  // namespace aerial::testing
