#include "aerial/render/shadow_cascades.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "aerial/scene/camera.h"

namespace aerial {
namespace {

CascadeFitInput NoonView() {
  CascadeFitInput in;
  in.camera.position = {130.0, -2400.0, 95.0};
  in.camera.yaw_deg = 20.0;
  in.camera.pitch_deg = 4.0;
  in.camera.vertical_fov_deg = 50.0;
  in.sun = DirectionFromZenithAzimuth(70.0, 160.0);
  in.casters = {{0.0, 0.0, 0.0}, 101e3};
  return in;
}

glm::dvec3 Clip(const ShadowCascade& c, const glm::dvec3& p) { return glm::dvec3(c.clip_from_world * glm::dvec4(p, 1.0)); }

// The slice's corners: the frustum's edges at its near and far view depths.
std::vector<glm::dvec3> SliceCorners(const CascadeFitInput& in, const ShadowCascade& c) {
  double tan_y = std::tan(glm::radians(in.camera.vertical_fov_deg / 2.0)), tan_x = tan_y * in.aspect;
  std::vector<glm::dvec3> corners;
  for (double depth : {c.near_m, c.far_m})
    for (double sx : {-1.0, 1.0})
      for (double sy : {-1.0, 1.0})
        corners.push_back(in.camera.position + depth * (Forward(in.camera) + sx * tan_x * Right(in.camera) +
                                                        sy * tan_y * Up(in.camera)));
  return corners;
}

TEST(ShadowCascades, SplitsRunFromTheNearPlaneToTheTerrainsEdge) {
  Camera camera;
  EXPECT_EQ(ShadowSplitM(camera, 0), camera.near_m);
  EXPECT_DOUBLE_EQ(ShadowSplitM(camera, 1), kFirstShadowSplitM);
  EXPECT_NEAR(ShadowSplitM(camera, kShadowCascades), kShadowFarM, 1e-6);
  for (int i = 0; i < kShadowCascades; ++i) EXPECT_LT(ShadowSplitM(camera, i), ShadowSplitM(camera, i + 1));
}

// Every corner of each slice lands inside its cascade's depth map, kShadowMarginTexels from its
// edges, and inside its depth range, for views in several directions and suns from noon to the
// horizon.
TEST(ShadowCascades, EachCascadeCoversItsSliceOfTheFrustum) {
  for (double yaw : {0.0, 95.0, 230.0}) {
    for (double sun_zenith : {5.0, 45.0, 89.0}) {
      CascadeFitInput in = NoonView();
      in.camera.yaw_deg = yaw;
      in.sun = DirectionFromZenithAzimuth(sun_zenith, 250.0);
      ShadowCascades cascades = FitShadowCascades(in);
      const double inner = 1.0 - 2.0 * kShadowMarginTexels / in.tile_texels;
      for (const ShadowCascade& c : cascades) {
        for (const glm::dvec3& corner : SliceCorners(in, c)) {
          glm::dvec3 clip = Clip(c, corner);
          EXPECT_LE(std::fabs(clip.x), inner + 1e-9) << "yaw " << yaw << " sun " << sun_zenith << " far " << c.far_m;
          EXPECT_LE(std::fabs(clip.y), inner + 1e-9);
          EXPECT_GE(clip.z, 0.0);
          EXPECT_LE(clip.z, 1.0);
        }
      }
    }
  }
}

// A caster anywhere in the caster bounds between a receiver and the sun is inside the depth
// range (not clipped away), nearer the sun than the receiver.
TEST(ShadowCascades, CastersTowardTheSunAreInsideTheDepthRange) {
  CascadeFitInput in = NoonView();
  in.sun = DirectionFromZenithAzimuth(85.0, 180.0);
  ShadowCascades cascades = FitShadowCascades(in);
  glm::dvec3 receiver = in.camera.position + 30.0 * Forward(in.camera);
  glm::dvec3 mountain = receiver + 90e3 * in.sun;  // 90 km toward the low sun, inside the bounds
  ASSERT_LT(glm::length(mountain - in.casters.center), in.casters.radius_m);
  const ShadowCascade& first = cascades[0];
  EXPECT_LE(Clip(first, mountain).z, 1.0);
  EXPECT_GT(Clip(first, mountain).z, Clip(first, receiver).z);
  EXPECT_NEAR(Clip(first, mountain).x, Clip(first, receiver).x, 1e-9);
}

// The texel size depends on the slice, the field of view and the aspect only: turning the camera
// keeps it, so edges keep their size on screen as the view turns.
TEST(ShadowCascades, TexelSizeDoesNotChangeAsTheCameraTurns) {
  CascadeFitInput in = NoonView();
  ShadowCascades before = FitShadowCascades(in);
  in.camera.yaw_deg += 33.0;
  in.camera.pitch_deg -= 20.0;
  ShadowCascades after = FitShadowCascades(in);
  for (int i = 0; i < kShadowCascades; ++i) EXPECT_DOUBLE_EQ(before[i].texel_m, after[i].texel_m);
  EXPECT_LT(before[0].texel_m, 0.15) << "sharp near the camera (1024 texels)";
}

// Texel snapping: after a move of a fraction of a texel, or of many texels, a fixed world point
// lands on the same place within its texel: its texel coordinates move by whole texels, so the
// rasterized shadow edges do not shimmer. A move smaller than half a texel changes no fit at all,
// so a cached shadow map stays valid.
TEST(ShadowCascades, TexelSnappingIsStableUnderCameraMoves) {
  CascadeFitInput in = NoonView();
  ShadowCascades before = FitShadowCascades(in);
  const glm::dvec3 point = in.camera.position + glm::dvec3(17.3, 41.9, -3.1);
  for (glm::dvec3 move : {glm::dvec3(0.013, -0.007, 0.002), glm::dvec3(3.71, 2.2, -0.4), glm::dvec3(251.0, -97.3, 12.0)}) {
    CascadeFitInput moved = in;
    moved.camera.position += move;
    ShadowCascades after = FitShadowCascades(moved);
    for (int i = 0; i < kShadowCascades; ++i) {
      double texels_per_clip = in.tile_texels / 2.0;
      glm::dvec2 shift = (glm::dvec2(Clip(after[i], point)) - glm::dvec2(Clip(before[i], point))) * texels_per_clip;
      EXPECT_NEAR(shift.x, std::round(shift.x), 1e-6) << "cascade " << i << " move " << move.x;
      EXPECT_NEAR(shift.y, std::round(shift.y), 1e-6) << "cascade " << i << " move " << move.x;
    }
  }
  CascadeFitInput nudged = in;
  nudged.camera.position += glm::dvec3(0.001, 0.0, 0.0);
  ShadowCascades after = FitShadowCascades(nudged);
  int unchanged = 0;
  for (int i = 0; i < kShadowCascades; ++i) unchanged += after[i].clip_from_world == before[i].clip_from_world;
  EXPECT_GE(unchanged, kShadowCascades - 1) << "a 1 mm move changes at most the cascade whose centre crossed a texel";
}

HeldCascades Held(const ShadowCascades& cascades) {
  HeldCascades held;
  for (int i = 0; i < kShadowCascades; ++i) held[i] = cascades[i];
  return held;
}

// A held window is kept while its slice fits: after a 5 m step every window stays (the same
// projection, so the shadow map's tile stays valid) and its slice has drifted into its slack; a
// 40 m step takes the first slice (57 m across, 14 m of slack) out of its window, which is fitted
// anew, while the larger ones stay; a sun 0.1 degree away refits them all.
TEST(ShadowCascades, HeldWindowsAreKeptWhileTheirSlicesFit) {
  CascadeFitInput in = NoonView();
  ShadowCascades first = FitShadowCascades(in);
  for (const ShadowCascade& c : first) EXPECT_EQ(c.drift, 0.0);
  CascadeFitInput stepped = in;
  stepped.camera.position += glm::dvec3(3.0, 4.0, 0.0);
  ShadowCascades kept = FitShadowCascades(stepped, Held(first));
  for (int i = 0; i < kShadowCascades; ++i) {
    EXPECT_EQ(kept[i].clip_from_world, first[i].clip_from_world) << "cascade " << i;
    EXPECT_GT(kept[i].drift, 0.0) << "cascade " << i;
    EXPECT_LE(kept[i].drift, 1.0) << "cascade " << i;
  }
  EXPECT_GT(kept[0].drift, kept[3].drift) << "the first slice's slack is the smallest";
  stepped.camera.position += glm::dvec3(40.0, 0.0, 0.0);
  ShadowCascades moved = FitShadowCascades(stepped, Held(kept));
  EXPECT_NE(moved[0].clip_from_world, first[0].clip_from_world);
  EXPECT_EQ(moved[0].drift, 0.0);
  for (int i = 1; i < kShadowCascades; ++i) EXPECT_EQ(moved[i].clip_from_world, first[i].clip_from_world) << i;
  CascadeFitInput sun = stepped;
  sun.sun = DirectionFromZenithAzimuth(70.1, 160.0);
  ShadowCascades resunned = FitShadowCascades(sun, Held(moved));
  for (int i = 0; i < kShadowCascades; ++i) EXPECT_NE(resunned[i].clip_from_world, moved[i].clip_from_world) << i;
}

// Every slice corner of the view lies inside its cascade's tile (kShadowMarginTexels from its
// edges), inside the depth range and inside the casters' rectangle, in the light's axes of the sun
// the cascade was drawn for.
void ExpectSlicesCovered(const CascadeFitInput& in, const ShadowCascades& cascades, int step) {
  const double inner = 1.0 - 2.0 * kShadowMarginTexels / in.tile_texels;
  for (const ShadowCascade& c : cascades) {
    const LightBasis light_axes = MakeLightBasis(c.toward_sun);
    for (const glm::dvec3& corner : SliceCorners(in, c)) {
      glm::dvec3 clip = Clip(c, corner);
      ASSERT_LE(std::fabs(clip.x), inner + 1e-9) << "step " << step << " far " << c.far_m;
      ASSERT_LE(std::fabs(clip.y), inner + 1e-9) << "step " << step << " far " << c.far_m;
      ASSERT_GE(clip.z, 0.0);
      ASSERT_LE(clip.z, 1.0);
      glm::dvec2 light(glm::dot(corner, light_axes.right), glm::dot(corner, light_axes.up));
      ASSERT_TRUE(glm::all(glm::lessThanEqual(c.casters_min, light + 1e-6)) &&
                  glm::all(glm::lessThanEqual(light, c.casters_max + 1e-6)))
          << "step " << step << " far " << c.far_m;
    }
  }
}

// However a camera walks and turns, the windows it keeps hold every slice corner as fresh fits
// do: a walk of 60 steps of 7 m that turns 1.5 degrees a step and climbs.
TEST(ShadowCascades, KeptWindowsCoverTheirSlicesAlongAWalk) {
  CascadeFitInput in = NoonView();
  ShadowCascades cascades = FitShadowCascades(in);
  int refits = 0;
  for (int step = 0; step < 60; ++step) {
    in.camera.position += 7.0 * Forward(in.camera) + glm::dvec3(0.0, 0.0, 1.5);
    in.camera.yaw_deg += 1.5;
    ShadowCascades next = FitShadowCascades(in, Held(cascades));
    for (int i = 0; i < kShadowCascades; ++i) refits += next[i].clip_from_world != cascades[i].clip_from_world;
    cascades = next;
    ExpectSlicesCovered(in, cascades, step);
  }
  // Without kept windows all 240 tiles would be fitted anew (and redrawn); the walk takes the first
  // slice out of its 14 m of slack every few steps and the larger ones seldom (measured: 45).
  std::printf("kept windows: %d refits in 60 steps of 4 cascades\n", refits);
  EXPECT_LT(refits, 60);
  EXPECT_GT(refits, 5);
}

// A window allowed to keep the sun it was drawn for stays with that sun (its projection, so its
// tile, unchanged) while its slice fits in its own light axes; one that must be fitted anew is
// fitted for the new sun, and one not allowed to keep its sun is refitted too.
TEST(ShadowCascades, HeldWindowsMayKeepTheSunTheyWereDrawnFor) {
  CascadeFitInput in = NoonView();
  const ShadowCascades first = FitShadowCascades(in);
  CascadeFitInput later = in;
  later.sun = DirectionFromZenithAzimuth(70.5, 161.0);
  later.camera.position += glm::dvec3(3.0, 4.0, 0.0);
  std::array<bool, kShadowCascades> keep{true, true, true, true};
  keep[2] = false;
  const ShadowCascades kept = FitShadowCascades(later, Held(first), keep);
  for (int i = 0; i < kShadowCascades; ++i) {
    EXPECT_EQ(kept[i].clip_from_world == first[i].clip_from_world, keep[i]) << "cascade " << i;
    EXPECT_EQ(kept[i].toward_sun, keep[i] ? in.sun : later.sun) << "cascade " << i;
  }
  later.camera.position += glm::dvec3(40.0, 0.0, 0.0);
  const ShadowCascades moved = FitShadowCascades(later, Held(kept), keep);
  EXPECT_EQ(moved[0].toward_sun, later.sun) << "the first slice left its window: a new one, for the new sun";
  EXPECT_EQ(moved[1].clip_from_world, first[1].clip_from_world);
  ExpectSlicesCovered(later, moved, 0);
}

// A walk under a sun that sinks 0.4 degrees a step, the tiles catching up one a step in turn (as
// the renderer's policy does): every kept window still covers its slice in its own sun's axes.
TEST(ShadowCascades, KeptWindowsCoverTheirSlicesUnderAMovingSun) {
  CascadeFitInput in = NoonView();
  ShadowCascades cascades = FitShadowCascades(in);
  for (int step = 0; step < 40; ++step) {
    in.camera.position += 7.0 * Forward(in.camera);
    in.camera.yaw_deg += 1.0;
    in.sun = DirectionFromZenithAzimuth(70.0 + 0.4 * (step + 1), 160.0);
    std::array<bool, kShadowCascades> keep{true, true, true, true};
    keep[step % kShadowCascades] = false;
    cascades = FitShadowCascades(in, Held(cascades), keep);
    EXPECT_EQ(cascades[step % kShadowCascades].toward_sun, in.sun) << "step " << step;
    ExpectSlicesCovered(in, cascades, step);
  }
}

}  // namespace
}  // namespace aerial
