// The sun's shadow map on surfaces (src/aerial/render/shadow_map.h, shaders/include/shadow.glsl),
// checked from the lit surface radiance the renderer draws without aerial perspective
// (Renderer::ReadSurface): with shadows off (S_off), on (S_on) and the sky's part alone (S_sky),
// the sun's visibility at a pixel is V = (S_on - S_sky) / (S_off - S_sky), exactly as the shaders
// apply it (ShadeLambertian: sun V + sky), whatever the Gouraud interpolation of the two parts.
// Whether the sun is hidden is decided on the CPU from the terrain's height function alone
// (scene/terrain.h), never from the renderer.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "aerial/render/renderer.h"
#include "aerial/render/shadow_cascades.h"
#include "aerial/scene.h"
#include "aerial/scene/camera.h"
#include "aerial/scene/primitives.h"
#include "aerial/scene/terrain.h"
#include "aerial/shader_abi/frame_geometry.h"
#include "aerial/validation/image_metrics.h"
#include "aerial/validation/reference_sampling.h"
#include "aerial/vk/resources.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;

// The three surface images of one view (green channel, the middle wavelength, and distance).
struct SurfaceImages {
  ImageRgbF on, off, sky;
  FrameUniforms frame;

  // The sun's visibility at a pixel, when its sun term is large enough to divide by (at least 5%
  // of the pixel's radiance without shadows); nullopt where the pixel is sky or the sun grazes.
  std::optional<double> Visibility(int x, int y) const {
    if (validation::IsSky(off, x, y)) return std::nullopt;
    double sun = off.pixel(x, y)[1] - sky.pixel(x, y)[1];
    if (!(sun > 0.05 * off.pixel(x, y)[1])) return std::nullopt;
    return (on.pixel(x, y)[1] - sky.pixel(x, y)[1]) / sun;
  }
  double Distance(int x, int y) const { return off.pixel(x, y)[3]; }
};

SurfaceImages RenderSurfaces(const Scene& scene, int width = kWidth, int height = kHeight) {
  const AtmosphereTables& tables = SmallTables();
  Renderer shadowed(tables, scene, {.width = width, .height = height, .shadows = true});
  Renderer unshadowed(tables, scene, {.width = width, .height = height, .shadows = false});
  shadowed.Render(scene);
  unshadowed.Render(scene);
  return {shadowed.ReadSurface(), unshadowed.ReadSurface(), shadowed.ReadSurface(SurfaceLight::kSkyOnly),
          shadowed.frame_uniforms()};
}

// The built-in terrain seen from a preset, without the meshes: only the terrain casts shadows,
// so the CPU's height function decides every one.
Scene TerrainOnly(const std::string& preset, double R) {
  Scene scene = BuildPreset(preset, R);
  scene.meshes.clear();
  return scene;
}

enum class SunSeen { kHidden, kVisible, kUnsure };

// The texel of the cascade whose slice of view depth holds the point (shadow_cascades.h): the
// shader may pick a finer one that also holds it, never a coarser one.
double CascadeTexelM(const Scene& scene, double aspect, const glm::dvec3& point) {
  ShadowCascades cascades = FitShadowCascades(
      {.camera = scene.camera, .aspect = aspect, .sun = scene.sun.Direction(), .tile_texels = kShadowTileTexels});
  double depth = glm::dot(point - scene.camera.position, Forward(scene.camera));
  for (const ShadowCascade& c : cascades)
    if (depth <= c.far_m) return c.texel_m;
  return cascades.back().texel_m;
}

// March from a terrain point toward the sun over the height function. The renderer draws a level
// of detail within 4 px (about 0.5% of the distance at 720 rows, lod_selection.h) of the surface,
// and its shadow edges are blurred and offset by up to 3 texels of the cascade (PCF reach and
// normal offset, shadow.glsl), so only clear cases count: hidden when the ray passes below the
// surface by more than 2 m + 1% of the caster's distance from the camera; visible when it stays
// above by as much beyond 50 m (nearer, only above); the same from points displaced by 3.5
// texels to either side across the sun's direction and upward, so that no shadow edge passes
// within the filter's reach and the normal offset.
// on_surface: the point is on the terrain (the shifted starts are put back onto it); otherwise it
// is a point in the air, and the starts stay where the shift puts them.
// A march stops as soon as nothing further along can change the verdict: once the ray is hidden
// (and so not visible); once it is not visible where only its staying visible could still matter;
// and once it is higher above the planet than the highest terrain by more than the margin while
// climbing faster than the margin grows (its height's rate, the cosine to the local vertical, only
// grows along a straight ray; the margin's is at most 0.01), so that it stays clear of the terrain.
SunSeen MarchTowardTheSun(const glm::dvec3& point, const Scene& scene, double aspect, double R,
                          bool on_surface = true) {
  const glm::dvec3 sun = scene.sun.Direction(), camera = scene.camera.position, center(0.0, 0.0, -R);
  glm::dvec3 side = glm::normalize(glm::cross(sun, glm::dvec3(0, 0, 1)));
  glm::dvec3 across = glm::cross(side, sun);
  double offset = 3.5 * CascadeTexelM(scene, aspect, point);
  bool all_hidden = true, all_visible = true;
  for (glm::dvec3 shift : {glm::dvec3(0.0), side, -side, across, -across, glm::dvec3(0, 0, 1)}) {
    glm::dvec3 start = point + shift * offset;
    if (on_surface && shift.z != 1.0) start += glm::dvec3(0, 0, -HeightAboveTerrainM(start, R));
    bool hidden = false, visible = true;
    for (double t = 0.5; t < 150e3; t *= 1.02) {
      glm::dvec3 p = start + sun * t;
      double h = HeightAboveTerrainM(p, R), margin = 2.0 + 0.01 * glm::length(p - camera);
      if (h < -margin) hidden = true;
      if (h < (t > 50.0 ? margin : 0.0)) visible = false;
      if (hidden || (!visible && !all_hidden)) break;
      const double altitude = glm::length(p - center) - R;
      if (altitude - kTerrainMaxHeightM > margin && glm::dot(glm::normalize(p - center), sun) >= 0.01) break;
    }
    all_hidden = all_hidden && hidden;
    all_visible = all_visible && visible;
    if (!all_hidden && !all_visible) return SunSeen::kUnsure;
  }
  return all_hidden ? SunSeen::kHidden : all_visible ? SunSeen::kVisible : SunSeen::kUnsure;
}

glm::dvec3 PixelPoint(const SurfaceImages& images, const Scene& scene, int x, int y) {
  return scene.camera.position + validation::PixelRay(images.frame, x, y) * images.Distance(x, y);
}

class ShadowRender : public GpuTest {};

// The evening preset: the sun 11 degrees above the western ridges, whose shadows cross the
// valley 0.5 to 1 km ahead. Where the CPU finds the sun hidden, the sun term is gone (V <= 1%: the PCF's weights
// of texels that see the sun, which a clear case never has); where it finds it seen, the
// surface is as bright as without shadows within 1%.
TEST_F(ShadowRender, SunTermIsZeroWhereTheTerrainHidesTheSunAndUnchangedWhereItIsSeen) {
  const double R = SmallTables().atmosphere().bottom_radius_m;
  Scene scene = TerrainOnly("evening", R);
  SurfaceImages images = RenderSurfaces(scene);
  int hidden = 0, visible = 0, bad_hidden = 0, bad_visible = 0;
  double worst_hidden = 0.0, worst_visible = 0.0;
  for (int y = 0; y < kHeight; y += 3) {
    for (int x = 0; x < kWidth; x += 3) {
      std::optional<double> v = images.Visibility(x, y);
      if (!v) continue;
      glm::dvec3 p = PixelPoint(images, scene, x, y);
      // Terrain (not the bare sphere beyond it) within the cascades' reach, kShadowFarM of view
      // depth: beyond, nothing is shadowed.
      if (images.Distance(x, y) > 0.9 * kShadowFarM) continue;
      if (std::fabs(HeightAboveTerrainM(p, R)) > 1.0 + 0.01 * images.Distance(x, y)) continue;
      switch (MarchTowardTheSun(p, scene, double(kWidth) / kHeight, R)) {
        case SunSeen::kHidden:
          ++hidden;
          worst_hidden = std::max(worst_hidden, *v);
          if (*v > 0.01) {
            ++bad_hidden;
            std::printf("lit where hidden: pixel %d %d, %.0f m away, V %.3f\n", x, y, images.Distance(x, y), *v);
          }
          break;
        case SunSeen::kVisible:
          ++visible;
          worst_visible = std::max(worst_visible, std::fabs(*v - 1.0));
          if (std::fabs(*v - 1.0) > 0.01) {
            ++bad_visible;
            std::printf("shadowed where seen: pixel %d %d, %.0f m away, V %.3f\n", x, y, images.Distance(x, y), *v);
          }
          break;
        case SunSeen::kUnsure:
          break;
      }
    }
  }
  std::printf("hidden: %d pixels, largest V %.4f; visible: %d pixels, largest |V - 1| %.4f\n", hidden,
              worst_hidden, visible, worst_visible);
  EXPECT_GE(hidden, 50) << "the view must show terrain in the ridges' shadow";
  EXPECT_GE(visible, 50) << "and sunlit terrain";
  EXPECT_EQ(bad_hidden, 0);
  EXPECT_EQ(bad_visible, 0);
}

// The depth a tile holds is where the sun's rays first meet the terrain: the terrain's triangles
// turned away from the sun are culled (shadow_map.cpp), and only those never hold that depth. The
// evening sun is 11 degrees up; over a grid of the third cascade's texels (20 m) the CPU marches
// each texel's sun ray down from the casters' top over the height function alone and finds where
// it enters the terrain. The casters are level-of-detail meshes, so each texel's depth is compared
// within a tolerance; measured, 98.2% of the texels lie within it and 1.7% beyond it. A tile that
// held the far sides of the hills instead (the culling the wrong way round) had 10.7% within and
// 89.2% beyond.
TEST_F(ShadowRender, TilesHoldWhereTheSunsRaysFirstMeetTheTerrain) {
  const AtmosphereTables& tables = SmallTables();
  const double R = tables.atmosphere().bottom_radius_m;
  const Scene scene = TerrainOnly("evening", R);
  Renderer renderer(tables, scene, {.width = kWidth, .height = kHeight, .shadows = true});
  renderer.Render(scene);
  const std::vector<float> atlas = vk::ReadImageFloats(SharedContext(), renderer.shadow_map().atlas());
  constexpr int kCascade = 2, kStride = 16;
  const ShadowCascade& tile = renderer.shadow_cascades()[kCascade];
  const LightBasis light = MakeLightBasis(tile.toward_sun);
  const int atlas_width = kShadowTileTexels * kShadowAtlasTilesPerRow;
  const glm::ivec2 corner((kCascade % kShadowAtlasTilesPerRow) * kShadowTileTexels,
                          (kCascade / kShadowAtlasTilesPerRow) * kShadowTileTexels);
  const double sin_elevation = glm::dot(tile.toward_sun, glm::dvec3(0, 0, 1));
  // Where the tile resolves the terrain, its casters lie within a quarter texel of the surface
  // (shadow_terrain.h): 1.3 texels along a ray 11 degrees up, and a texel's width across a
  // 45-degree slope moves the entry by as much again, so 3 texels. Farther out the casters are the
  // frame's own chunks, within 4 px on screen at 720 rows or more (lod_selection.h): 0.64% of their
  // distance from the camera, vertically, which a grazing ray stretches; 1% of that distance more.
  auto tolerance_m = [&](const glm::dvec3& entry) {
    return 3.0 * tile.texel_m + 0.01 * glm::length(entry - scene.camera.position);
  };
  int compared = 0, within = 0, beyond = 0;
  for (int v = kStride / 2; v < kShadowTileTexels; v += kStride) {
    for (int u = kStride / 2; u < kShadowTileTexels; u += kStride) {
      const glm::dvec2 xy = glm::dvec2(tile.center_light) +
                            (glm::dvec2(u + 0.5, v + 0.5) / double(kShadowTileTexels) * 2.0 - 1.0) * tile.radius_m;
      if (glm::any(glm::lessThan(xy, tile.casters_min)) || glm::any(glm::greaterThan(xy, tile.casters_max))) continue;
      auto at = [&](double s) { return light.right * xy.x + light.up * xy.y + light.toward_sun * s; };
      // Down the ray from the casters' top, in steps of the height above the terrain over 2.5: the ray
      // sinks 0.19 m a metre, so a step crosses no slope rising less than 2.3 m a metre (66 degrees)
      // toward it. A steeper one crossed would put the entry later, where the tile's depth would
      // count as nearer the sun than it, never beyond.
      std::optional<double> entry;
      for (double s = tile.depth_max_m; s > tile.depth_min_m;) {
        const glm::dvec3 p = at(s);
        const double h = HeightAboveTerrainM(p, R);
        if (h < 0.0) {
          // The terrain's own edge, where it fades into the bare sphere, is not compared.
          if (glm::length(glm::dvec2(SeaLevelPoint(p, R))) < 0.95 * kTerrainRadiusM) entry = s;
          break;
        }
        s -= std::max(0.25, h / 2.5);
      }
      if (!entry) continue;
      const float depth = atlas[size_t(corner.y + v) * atlas_width + corner.x + u];
      const double held = tile.depth_min_m + double(depth) * (tile.depth_max_m - tile.depth_min_m);
      const double tolerance = tolerance_m(at(*entry));
      ++compared;
      if (std::fabs(held - *entry) <= tolerance) ++within;
      if (held < *entry - tolerance) ++beyond;
    }
  }
  std::printf("cascade %d (texel %.1f m, sun %.1f degrees up): %d texels compared, %d within the tolerance of the "
              "CPU's entry, %d beyond it\n",
              kCascade, tile.texel_m, std::asin(sin_elevation) * 180.0 / std::numbers::pi, compared, within, beyond);
  EXPECT_GE(compared, 1000) << "the tile must show terrain";
  EXPECT_GE(within, 0.95 * compared);
  EXPECT_LE(beyond, 0.04 * compared);
}

// No shadow acne: at noon (sun 20 degrees from the zenith) the flat valley floor that the CPU
// finds sunlit has the same spread of radiance with shadows as without: its relative standard
// deviation is the same within 1% of itself, and no pixel loses more than 1% (acne darkens
// texel-sized stripes by tens of percent).
TEST_F(ShadowRender, NoAcneOnTheFlatSunlitValleyFloorAtNoon) {
  const double R = SmallTables().atmosphere().bottom_radius_m;
  Scene scene = TerrainOnly("noon", R);
  scene.camera.pitch_deg = -12.0;  // mostly valley floor
  SurfaceImages images = RenderSurfaces(scene);
  std::vector<double> on, off;
  double darkest = 1.0;
  for (int y = 0; y < kHeight; y += 4) {
    for (int x = 0; x < kWidth; x += 4) {
      if (validation::IsSky(images.off, x, y)) continue;
      glm::dvec3 p = PixelPoint(images, scene, x, y);
      glm::dvec3 sea = SeaLevelPoint(p, R);
      TerrainSurface surface = TerrainSurfaceAt(sea.x, sea.y, R);
      glm::dvec3 up = glm::normalize(surface.point + glm::dvec3(0, 0, R));
      if (glm::dot(surface.normal, up) < 0.995) continue;  // within 5.7 degrees of flat
      if (MarchTowardTheSun(p, scene, double(kWidth) / kHeight, R) != SunSeen::kVisible) continue;
      on.push_back(images.on.pixel(x, y)[1]);
      off.push_back(images.off.pixel(x, y)[1]);
      darkest = std::min(darkest, on.back() / off.back());
    }
  }
  auto relative_spread = [](const std::vector<double>& values) {
    double mean = 0.0, square = 0.0;
    for (double v : values) mean += v / values.size();
    for (double v : values) square += (v - mean) * (v - mean) / values.size();
    return std::sqrt(square) / mean;
  };
  double spread_on = relative_spread(on), spread_off = relative_spread(off);
  std::printf("%zu flat sunlit pixels: relative spread %.5f with shadows, %.5f without; darkest %.4f\n",
              on.size(), spread_on, spread_off, darkest);
  ASSERT_GE(on.size(), 300u);
  EXPECT_NEAR(spread_on, spread_off, 0.01 * spread_off);
  EXPECT_GE(darkest, 0.99);
}

// No peter-panning: a 2 m x 2 m pillar 8 m tall stands 20 m from the camera, which looks at its
// west face, the sun 30 degrees up in the east. Measure: the visibility of the ground beside the
// shaded west face at distances s from it, on pixels that show that ground (within 0.3 m: a
// pixel spans ~0.3 m of ground along the view at this grazing angle). The shadow must start at
// the contact line: V <= 5% from s = 5 cm on (the first cascade's texel is 11 cm, the normal
// offset 1.5 of them), while the ground south of the pillar, in the sun, keeps V >= 95%.
TEST_F(ShadowRender, ShadowStartsAtTheBaseOfAStandingPillar) {
  const double R = SmallTables().atmosphere().bottom_radius_m;
  Scene scene = TerrainOnly("noon", R);
  GroundFrame base = GroundFrameAt(0.0, 20.0, R);
  Mesh pillar{.name = "pillar"};
  AppendBox(pillar, base.origin - base.up * 0.5, base.east, base.north, {2.0, 2.0, 8.5}, {{0.45f, 0.45f, 0.45f}});
  scene.meshes.push_back(pillar);
  scene.camera.position = base.origin - base.north * 20.0 - base.east * 8.0 + base.up * 3.0;
  scene.camera.pitch_deg = -8.0;
  scene.camera.yaw_deg = glm::degrees(std::atan2(8.0, 20.0));
  scene.sun = {60.0, 90.0};
  const int width = 640, height = 360;
  SurfaceImages images = RenderSurfaces(scene, width, height);
  glm::dmat4 view_projection = ProjectionMatrix(scene.camera, double(width) / height) * ViewMatrix(scene.camera);
  // The visibility at the pixel showing the ground point (x, y), if that pixel shows it.
  auto ground_visibility = [&](double x, double y) -> std::optional<double> {
    glm::dvec3 p = TerrainPoint(x, y, R);
    glm::dvec4 clip = view_projection * glm::dvec4(p, 1.0);
    int px = int((clip.x / clip.w * 0.5 + 0.5) * width), py = int((clip.y / clip.w * 0.5 + 0.5) * height);
    if (px < 0 || py < 0 || px >= width || py >= height) return std::nullopt;
    if (glm::length(PixelPoint(images, scene, px, py) - p) > 0.3) return std::nullopt;
    return images.Visibility(px, py);
  };
  int measured = 0;
  for (double s : {0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0}) {
    for (double along : {-0.6, 0.0, 0.6}) {
      std::optional<double> shaded = ground_visibility(-1.0 - s, 20.0 + along);
      if (!shaded) continue;
      ++measured;
      EXPECT_LE(*shaded, 0.05) << s << " m west of the pillar, " << along << " m north of its centre";
    }
  }
  EXPECT_GE(measured, 12) << "the ground beside the pillar must be in view";
  for (double x : {-0.6, 0.0, 0.6}) {
    std::optional<double> lit = ground_visibility(x, 17.5);
    ASSERT_TRUE(lit.has_value());
    EXPECT_GE(*lit, 0.95) << "south of the pillar, in the sun";
  }
}

// The shadow map is drawn on the first frame, kept while nothing moves, and redrawn when the sun
// moves; with shadows off it is never drawn.
TEST_F(ShadowRender, ShadowMapIsRedrawnOnlyWhenTheSunOrTheFitChanges) {
  const AtmosphereTables& tables = SmallTables();
  Scene scene = BuildPreset("noon", tables.atmosphere().bottom_radius_m);
  Renderer renderer(tables, scene, {.width = kWidth, .height = kHeight});
  renderer.Render(scene);
  EXPECT_TRUE(renderer.frame_info().shadow_map_updated);
  renderer.Render(scene);
  EXPECT_FALSE(renderer.frame_info().shadow_map_updated) << "a still view";
  scene.sun.zenith_deg += 0.5;
  renderer.Render(scene);
  EXPECT_TRUE(renderer.frame_info().shadow_map_updated) << "the sun moved";
  scene.camera.position.x += 500.0;
  renderer.Render(scene);
  EXPECT_TRUE(renderer.frame_info().shadow_map_updated) << "the camera moved by many texels";
  Renderer off(tables, scene, {.width = kWidth, .height = kHeight, .shadows = false});
  off.Render(scene);
  EXPECT_FALSE(off.frame_info().shadow_map_updated);
}

// Under a moving sun the tiles catch up one a frame (frame_cache_policy.h): each frame of a sun
// that sinks 0.3 degrees a frame redraws one tile and is not settled while a tile lags; once the
// sun stops the view settles within kShadowCascades - 1 frames, on the frame that a fresh
// renderer draws for that sun (a still camera fits the same windows). The same frames without
// shadows are the baseline, as for kept tiles: the shadows may add 1e-5 of relative RMSE to it,
// where they change the frame by several percent.
TEST_F(ShadowRender, MovingSunRedrawsOneTileAFrameAndSettlesOnTheFreshFrame) {
  const AtmosphereTables& tables = SmallTables();
  const Scene start = BuildPreset("evening", tables.atmosphere().bottom_radius_m);
  auto sweep = [&](bool shadows) {
    Renderer streamed(tables, start, {.width = kWidth, .height = kHeight, .shadows = shadows});
    streamed.Render(start);
    Scene scene = start;
    for (int frame = 0; frame < 5; ++frame) {
      scene.sun.zenith_deg += 0.3;
      streamed.Render(scene, /*complete=*/false);
      if (!shadows) continue;
      EXPECT_EQ(streamed.frame_info().shadow_tiles_redrawn, 1) << "frame " << frame;
      EXPECT_FALSE(streamed.frame_info().settled) << "frame " << frame;
    }
    int frames_to_settle = 0;
    while (!streamed.frame_info().settled && frames_to_settle < 10) {
      streamed.Render(scene, /*complete=*/false);
      ++frames_to_settle;
    }
    Renderer fresh(tables, scene, {.width = kWidth, .height = kHeight, .shadows = shadows});
    fresh.Render(scene);
    ImageRgbF image = fresh.ReadOutput();
    return std::tuple{validation::EnergyWeightedRelativeRmse(streamed.ReadOutput(), image), image, frames_to_settle};
  };
  auto [caught_up_vs_fresh, shadowed, frames_to_settle] = sweep(true);
  EXPECT_GE(frames_to_settle, 1) << "three tiles lagged when the sun stopped";
  EXPECT_LE(frames_to_settle, kShadowCascades - 1);
  auto [baseline, unshadowed, unshadowed_frames] = sweep(false);
  double shadows = validation::EnergyWeightedRelativeRmse(shadowed, unshadowed);
  std::printf("caught-up tiles vs fresh: %.2e relative RMSE, without shadows %.2e (the shadows: %.2f%%)\n",
              caught_up_vs_fresh, baseline, 100 * shadows);
  EXPECT_LT(caught_up_vs_fresh, baseline + 1e-5);
  EXPECT_GT(shadows, 0.05) << "the shadows must matter for the comparison to mean something";
}

// A camera that steps 5 m keeps every tile of the shadow map (shadow_cascades.h: each window
// holds its slice with slack), yet draws the frame that a renderer fitting fresh windows at the
// new view draws: both windows are snapped to the same texel grid of the same size, so their
// tiles hold the same depths, shifted by whole texels. The streamed frame also keeps its sky-view
// table 5 m off, so the same step without shadows is the baseline: the shadows may add 1e-5 of
// relative RMSE to it (measured: 8e-8 with a fresh sky-view table), where they change the frame
// by 9.6%. A 500 m step leaves the first window behind (and changes the terrain's level of
// detail): tiles are redrawn. (A one-off frame fits fresh windows:
// LeanFrame.OneOffFramesAreCompleteWhateverCameBefore.)
TEST_F(ShadowRender, KeptTilesDrawTheFrameThatFreshOnesDraw) {
  const AtmosphereTables& tables = SmallTables();
  const Scene start = BuildPreset("evening", tables.atmosphere().bottom_radius_m);
  Scene stepped = start;
  stepped.camera.position += 5.0 * Forward(stepped.camera);
  // The stepped frame drawn by a renderer that drew the start first (a stream, as the viewer
  // draws), and by a fresh one.
  auto step = [&](bool shadows, Renderer& streamed) {
    streamed.Render(start);
    streamed.Render(stepped, /*complete=*/false);
    Renderer fresh(tables, stepped, {.width = kWidth, .height = kHeight, .shadows = shadows});
    fresh.Render(stepped);
    ImageRgbF image = fresh.ReadOutput();
    return std::pair{validation::EnergyWeightedRelativeRmse(streamed.ReadOutput(), image), image};
  };
  Renderer kept(tables, start, {.width = kWidth, .height = kHeight});
  auto [kept_vs_fresh, shadowed] = step(true, kept);
  EXPECT_EQ(kept.frame_info().shadow_tiles_redrawn, 0);
  EXPECT_TRUE(kept.frame_info().froxels_updated);
  Renderer unshadowed(tables, start, {.width = kWidth, .height = kHeight, .shadows = false});
  auto [baseline, unshadowed_image] = step(false, unshadowed);
  double shadows = validation::EnergyWeightedRelativeRmse(shadowed, unshadowed_image);
  std::printf("kept tiles vs fresh: %.2e relative RMSE, without shadows %.2e (the shadows themselves: %.2f%%)\n",
              kept_vs_fresh, baseline, 100 * shadows);
  EXPECT_LT(kept_vs_fresh, baseline + 1e-5);
  EXPECT_GT(shadows, 0.05) << "the shadows must matter for the comparison to mean something";
  stepped.camera.position += 500.0 * Forward(stepped.camera);
  kept.Render(stepped, /*complete=*/false);
  EXPECT_GE(kept.frame_info().shadow_tiles_redrawn, 1) << "the first window left behind";
}

// A camera flying 25 m a frame keeps the far windows, whose terrain casters change as its level of
// detail does: those tiles are redrawn only where the chunks changed (shadow_tile_region.h). After
// eight frames the shadow map is what the same flight draws with those tiles redrawn whole, but
// for float rounding: each redraw places the casters relative to its own frame's camera, so a
// depth may differ in its last bits (measured: 1872 of the atlas' 4M texels by 1e-6 to 1e-5) and,
// where an edge passes within that rounding of a texel's centre, the texel may show the next
// caster (10 texels by over 1e-5), which moves the view by 5.9e-6 relative RMSE (the froxel rows,
// gathered at the horizon, pass those texels). Not clearing the region leaves the replaced chunks'
// depths: 1343 texels over 1e-5. Drawing none of its chunks leaves holes and changes the view by 7%.
TEST_F(ShadowRender, ChangedCastersRedrawTheirTexelsAsAWholeTileRedrawWould) {
  const AtmosphereTables& tables = SmallTables();
  const Scene start = BuildPreset("evening", tables.atmosphere().bottom_radius_m);
  struct Flight {
    ImageRgbF view;
    std::vector<float> shadow_map;
    int regions_redrawn = 0;
  };
  auto fly = [&](bool regions) {
    RendererOptions options{{.width = kWidth, .height = kHeight}};
    options.shadow_tile_regions = regions;
    Renderer renderer(tables, start, options);
    renderer.Render(start);
    Scene scene = start;
    Flight flight;
    for (int frame = 0; frame < 8; ++frame) {
      scene.camera.position += 25.0 * Forward(scene.camera);
      renderer.Render(scene, /*complete=*/false);
      flight.regions_redrawn += renderer.frame_info().shadow_tile_regions_redrawn;
    }
    flight.view = renderer.ReadOutput();
    flight.shadow_map = vk::ReadImageFloats(SharedContext(), renderer.shadow_map().atlas());
    return flight;
  };
  const Flight in_part = fly(true), whole = fly(false);
  EXPECT_EQ(whole.regions_redrawn, 0);
  EXPECT_GE(in_part.regions_redrawn, 2) << "the flight must change the casters of a kept window";
  ASSERT_EQ(in_part.shadow_map.size(), whole.shadow_map.size());
  size_t off = 0;  // by more than rounding
  for (size_t t = 0; t < whole.shadow_map.size(); ++t)
    if (std::abs(in_part.shadow_map[t] - whole.shadow_map[t]) > 1e-5f) ++off;
  const double view = validation::EnergyWeightedRelativeRmse(in_part.view, whole.view);
  std::printf("%d tiles redrawn in part; against whole redraws: %zu texels off by over 1e-5, the view %.1e relative "
              "RMSE\n",
              in_part.regions_redrawn, off, view);
  EXPECT_LE(off, 50u);
  EXPECT_LE(view, 2e-5);
}

// A frame of a still view reads the sun visibility that the frame before it looked up
// (shaders/include/opaque_fragment.glsl): the same image to the bit, since the visibility is kept
// in float. Any move (here the sun's) makes the next frame look it up again. The evening preset
// has shadows on most of its terrain, so a cache read wrongly would change many pixels.
TEST_F(ShadowRender, StillFrameReadsTheCachedSunVisibilityAndMatchesTheLookup) {
  const AtmosphereTables& tables = SmallTables();
  Scene scene = BuildPreset("evening", tables.atmosphere().bottom_radius_m);
  Renderer renderer(tables, scene, {.width = kWidth, .height = kHeight});
  renderer.Render(scene);
  EXPECT_FALSE(renderer.frame_info().sun_visibility_cached) << "the first frame looks it up";
  ImageRgbF looked_up = renderer.ReadOutput();
  renderer.Render(scene, /*complete=*/false);
  EXPECT_TRUE(renderer.frame_info().sun_visibility_cached) << "a still view";
  ImageRgbF cached = renderer.ReadOutput();
  auto differing_pixels = [](const ImageRgbF& a, const ImageRgbF& b) {
    EXPECT_EQ(a.rgba.size(), size_t(kWidth) * kHeight * 4);
    EXPECT_EQ(b.rgba.size(), a.rgba.size());
    size_t different = 0;
    for (size_t i = 0; i + 4 <= std::min(a.rgba.size(), b.rgba.size()); i += 4)
      different += !std::equal(&a.rgba[i], &a.rgba[i] + 4, &b.rgba[i]);
    return different;
  };
  EXPECT_EQ(differing_pixels(cached, looked_up), 0u) << "pixels of the cached frame unlike the looked-up one";

  Renderer unshadowed(tables, scene, {.width = kWidth, .height = kHeight, .shadows = false});
  unshadowed.Render(scene);
  ImageRgbF off = unshadowed.ReadOutput();
  EXPECT_GT(differing_pixels(cached, off), size_t(kWidth) * kHeight / 10)
      << "pixels the shadows change: the cache must carry them";

  scene.sun.zenith_deg += 0.5;
  renderer.Render(scene, /*complete=*/false);
  EXPECT_FALSE(renderer.frame_info().sun_visibility_cached) << "the sun moved";
}

// ---- Shadowed in-scattering in the froxel volume (shaders/frame/froxel.comp) ----
// The evening preset's terrain, its froxel volume built with shadows on and off. The sun's
// visibility along a column is decided on the CPU at the points where the shader samples it
// (VISIBILITY_SAMPLES = 4 per slice step, at their centres) by the terrain march above; the Mie
// channel holds single scattering alone (multiple scattering is in the Rayleigh channel, divided
// by P_R), so its growth along a column is the single scattering the shadow must scale.
struct ShadowedVolumes {
  FroxelTexels on, off;
  FrameUniforms frame;
  Scene scene;
  double aspect;
};

ShadowedVolumes BuildEveningVolumes() {
  const AtmosphereTables& tables = SmallTables();
  double R = tables.atmosphere().bottom_radius_m;
  Scene scene = TerrainOnly("evening", R);
  auto build = [&](bool shadows) {
    Renderer renderer(tables, scene, {.width = kWidth, .height = kHeight, .shadows = shadows});
    renderer.Render(scene);
    return std::pair{renderer.froxels().Read(tables.context(), renderer.frame_uniforms()), renderer.frame_uniforms()};
  };
  auto [on, frame] = build(true);
  return {on, build(false).first, frame, scene, double(kWidth) / kHeight};
}

double MieGreen(const FroxelTexels& t, int x, int y, int slice) {
  return t.mie[((size_t(slice) * t.grid.height + y) * t.grid.width + x) * 4 + 1];
}
double RayleighGreen(const FroxelTexels& t, int x, int y, int slice) {
  return t.rayleigh[((size_t(slice) * t.grid.height + y) * t.grid.width + x) * 4 + 1];
}

// The CPU's verdict at the 4 visibility samples of each slice step of column (x, y), within the
// shadow map's reach (the shader sees the sun beyond its last cascade, 100 km of view depth).
std::vector<std::array<SunSeen, 4>> ColumnVisibility(const ShadowedVolumes& v, int x, int y, int slices) {
  const FroxelGrid& grid = v.on.grid;
  glm::dvec3 ray = ViewRayFromScreen(v.frame, v.on.axes.ScreenPosition({(x + 0.5) / grid.width, (y + 0.5) / grid.height}));
  double R = SmallTables().atmosphere().bottom_radius_m;
  std::vector<std::array<SunSeen, 4>> steps;
  double previous = 0.0;
  for (int k = 0; k < slices; ++k) {
    double distance = grid.SliceDistance(k + 0.5);
    std::array<SunSeen, 4> seen;
    for (int i = 0; i < 4; ++i) {
      double d = previous + (distance - previous) * (i + 0.5) / 4.0;
      glm::dvec3 point = v.scene.camera.position + ray * d;
      double depth = glm::dot(ray * d, Forward(v.scene.camera));
      seen[i] = depth > 90e3                    ? SunSeen::kUnsure
                : HeightAboveTerrainM(point, R) < 0.0 ? SunSeen::kUnsure  // under the ground
                                                      : MarchTowardTheSun(point, v.scene, v.aspect, R, false);
    }
    steps.push_back(seen);
    previous = distance;
  }
  return steps;
}

class FroxelShadows : public ShadowRender {};

// Where the CPU finds the sun seen from every sample of a column up to a slice, the shadowed
// volume equals the unshadowed one within 0.5% (the shadow lookup changes nothing
// where nothing occludes), and where it finds the sun hidden from every sample of a stretch of
// slices, single scattering does not grow there: the Mie channel's growth over the stretch is at
// most 2% of the unshadowed growth (the PCF's weights of texels that see the sun, which clear
// cases never have), while the Rayleigh channel still grows by the multiple scattering, which the
// shadow leaves alone.
TEST_F(FroxelShadows, UnoccludedColumnsUnchangedAndShadowedStretchesWithoutSingleScattering) {
  ShadowedVolumes v = BuildEveningVolumes();
  const int slices = v.on.grid.depth;
  int unoccluded = 0, shadowed = 0;
  double worst_unoccluded = 0.0, worst_shadowed = 0.0;
  double multiple_low = 1.0, multiple_high = 0.0;  // Rayleigh growth in shadow over the unshadowed
  for (int y = 0; y < v.on.grid.height; y += 4) {
    for (int x = 0; x < v.on.grid.width; x += 4) {
      auto seen = ColumnVisibility(v, x, y, slices);
      bool all_seen = true;
      for (int k = 0; k < slices; ++k) {
        for (SunSeen s : seen[k]) all_seen = all_seen && s == SunSeen::kVisible;
        bool hidden = true;
        for (SunSeen s : seen[k]) hidden = hidden && s == SunSeen::kHidden;
        if (all_seen) {
          double off = MieGreen(v.off, x, y, k), on = MieGreen(v.on, x, y, k);
          double ray_off = RayleighGreen(v.off, x, y, k), ray_on = RayleighGreen(v.on, x, y, k);
          worst_unoccluded = std::max({worst_unoccluded, std::abs(on / off - 1.0), std::abs(ray_on / ray_off - 1.0)});
          ++unoccluded;
        } else if (hidden && k > 0) {
          double grown_off = MieGreen(v.off, x, y, k) - MieGreen(v.off, x, y, k - 1);
          double grown_on = MieGreen(v.on, x, y, k) - MieGreen(v.on, x, y, k - 1);
          double rayleigh_on = RayleighGreen(v.on, x, y, k) - RayleighGreen(v.on, x, y, k - 1);
          double rayleigh_off = RayleighGreen(v.off, x, y, k) - RayleighGreen(v.off, x, y, k - 1);
          if (!(grown_off > 0.0)) continue;
          worst_shadowed = std::max(worst_shadowed, std::abs(grown_on) / grown_off);
          multiple_low = std::min(multiple_low, rayleigh_on / rayleigh_off);
          multiple_high = std::max(multiple_high, rayleigh_on / rayleigh_off);
          EXPECT_GT(rayleigh_on, 0.0) << x << " " << y << " " << k;
          EXPECT_LT(rayleigh_on, rayleigh_off) << x << " " << y << " " << k;
          ++shadowed;
        }
      }
    }
  }
  std::printf("froxels: %d unoccluded, worst %.4f%%; %d shadowed slice steps, Mie growth at most %.4f%% of the "
              "unshadowed, Rayleigh growth %.0f-%.0f%% of it\n",
              unoccluded, 100 * worst_unoccluded, shadowed, 100 * worst_shadowed, 100 * multiple_low,
              100 * multiple_high);
  EXPECT_GT(unoccluded, 100);
  EXPECT_GT(shadowed, 20);
  EXPECT_LE(worst_unoccluded, 0.005);
  EXPECT_LE(worst_shadowed, 0.02);
}

// Partly shadowed columns, checked on the CPU: each column's Mie channel at its last slice before
// the ground (or 80 km) against the unshadowed growth of each slice step times the fraction of the
// step's samples the CPU finds sunlit. Samples the CPU cannot decide (near a shadow edge, within
// the margins of MarchTowardTheSun) bracket the expectation: counted dark for its lower end, lit
// for its upper one. Bound: the bracket widened by 3% of the expectation (the shadow map draws a
// level of detail within 4 px of the terrain, and each step's visibility is the mean of 4 samples).
TEST_F(FroxelShadows, PartlyShadowedColumnsMatchTheCpuMarch) {
  ShadowedVolumes v = BuildEveningVolumes();
  double R = SmallTables().atmosphere().bottom_radius_m;
  int checked = 0;
  double worst = 0.0;  // outside the bracket, relative to its middle
  std::vector<double> widths;  // of the brackets, relative to their middle
  for (int y = 0; y < v.on.grid.height; y += 2) {
    for (int x = 0; x < v.on.grid.width; x += 2) {
      glm::dvec3 ray = ViewRayFromScreen(
          v.frame, v.on.axes.ScreenPosition({(x + 0.5) / v.on.grid.width, (y + 0.5) / v.on.grid.height}));
      int end = 0;  // slice steps whose samples are all in the air and within 80 km
      while (end < v.on.grid.depth && v.on.grid.SliceDistance(end + 0.5) < 80e3 &&
             HeightAboveTerrainM(v.scene.camera.position + ray * v.on.grid.SliceDistance(end + 0.5), R) > 0.0)
        ++end;
      if (end < 2) continue;
      auto seen = ColumnVisibility(v, x, y, end);
      double low = 0.0, high = 0.0;
      int lit = 0, dark = 0;
      for (int k = 0; k < end; ++k) {
        int visible = 0, unsure = 0;
        for (SunSeen s : seen[k]) {
          visible += s == SunSeen::kVisible;
          unsure += s == SunSeen::kUnsure;
        }
        lit += visible;
        dark += 4 - visible - unsure;
        double grown = MieGreen(v.off, x, y, k) - (k > 0 ? MieGreen(v.off, x, y, k - 1) : 0.0);
        low += grown * visible / 4.0;
        high += grown * (visible + unsure) / 4.0;
      }
      if (lit == 0 || dark == 0) continue;  // not partly shadowed
      double got = MieGreen(v.on, x, y, end - 1), middle = 0.5 * (low + high);
      double outside = std::max({0.0, low - got, got - high}) / middle;
      worst = std::max(worst, outside);
      widths.push_back((high - low) / middle);
      EXPECT_LE(outside, 0.03) << "column " << x << " " << y << ": " << got << " not in [" << low << ", " << high << "]";
      ++checked;
    }
  }
  const auto decided = std::count_if(widths.begin(), widths.end(), [](double w) { return w < 0.3; });
  std::nth_element(widths.begin(), widths.begin() + widths.size() / 2, widths.end());
  double median_width = widths.empty() ? 1.0 : widths[widths.size() / 2];
  std::printf("froxels: %d partly shadowed columns, worst %.3f%% outside the CPU march's bracket, "
              "median bracket %.2f%% wide, %td under 30%% wide\n", checked, 100 * worst, 100 * median_width, decided);
  EXPECT_GT(checked, 10);
  // The check means something only where the CPU decides most samples: a column's bracket spans
  // the single scattering of its undecided samples. The rows gather at the horizon (froxel_axes.h),
  // where rays graze the shadows' edges and leave more samples undecided (measured: median 69.6%
  // wide, 40 of 143 columns under 30%).
  EXPECT_GE(decided, 20);
}

}  // namespace
}  // namespace aerial::testing
