// The sun's shadow map on surfaces (src/aerial/render/shadow_map.h, shaders/include/shadow.glsl),
// checked from the lit surface radiance the renderer draws without aerial perspective
// (Renderer::ReadSurface): with shadows off (S_off), on (S_on) and the sky's part alone (S_sky),
// the sun's visibility at a pixel is V = (S_on - S_sky) / (S_off - S_sky), exactly as the shaders
// apply it (ShadeLambertian: sun V + sky), whatever the Gouraud interpolation of the two parts.
// Whether the sun is hidden is decided on the CPU from the terrain's height function alone
// (scene/terrain.h), never from the renderer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "aerial/bench/image_metrics.h"
#include "aerial/bench/reference_sampling.h"
#include "aerial/render/renderer.h"
#include "aerial/render/shadow_cascades.h"
#include "aerial/scene/camera.h"
#include "aerial/scene/presets.h"
#include "aerial/scene/primitives.h"
#include "aerial/scene/terrain.h"
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
    if (bench::IsSky(off, x, y)) return std::nullopt;
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
SunSeen MarchTowardTheSun(const glm::dvec3& point, const Scene& scene, double aspect, double R) {
  const glm::dvec3 sun = scene.sun.Direction(), camera = scene.camera.position;
  glm::dvec3 side = glm::normalize(glm::cross(sun, glm::dvec3(0, 0, 1)));
  glm::dvec3 across = glm::cross(side, sun);
  double offset = 3.5 * CascadeTexelM(scene, aspect, point);
  bool all_hidden = true, all_visible = true;
  for (glm::dvec3 shift : {glm::dvec3(0.0), side, -side, across, -across, glm::dvec3(0, 0, 1)}) {
    glm::dvec3 start = point + shift * offset;
    if (shift.z != 1.0) start += glm::dvec3(0, 0, -HeightAboveTerrainM(start, R));  // onto the surface
    bool hidden = false, visible = true;
    for (double t = 0.5; t < 150e3; t *= 1.02) {
      glm::dvec3 p = start + sun * t;
      double h = HeightAboveTerrainM(p, R), margin = 2.0 + 0.01 * glm::length(p - camera);
      if (h < -margin) hidden = true;
      if (h < (t > 50.0 ? margin : 0.0)) visible = false;
    }
    all_hidden = all_hidden && hidden;
    all_visible = all_visible && visible;
  }
  return all_hidden ? SunSeen::kHidden : all_visible ? SunSeen::kVisible : SunSeen::kUnsure;
}

glm::dvec3 PixelPoint(const SurfaceImages& images, const Scene& scene, int x, int y) {
  return scene.camera.position + bench::PixelRay(images.frame, x, y) * images.Distance(x, y);
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
      if (bench::IsSky(images.off, x, y)) continue;
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

}  // namespace
}  // namespace aerial::testing
