#include "aerial/render/frame_cache_policy.h"

#include <gtest/gtest.h>

#include <cmath>

#include "aerial/scene/camera.h"

namespace aerial {
namespace {

constexpr float kR = 6360e3f;

// A camera 100 m above the planet's surface, the sun 60 degrees from its zenith.
FrameUniforms Frame() {
  FrameUniforms frame{};
  frame.camera_planet_position = {0.0f, 0.0f, kR + 100.0f, 0.0f};
  frame.sun_direction = {std::sqrt(0.75f), 0.0f, 0.5f, 0.0f};
  frame.froxel_size = {32, 32, 32, 0};
  return frame;
}

std::vector<terrain::SelectedChunk> Chunks(int x) { return {{.id = {.level = 3, .x = x, .y = 1}}}; }

TEST(FrameCachePolicy, SameFrameIsBitEqual) {
  FrameUniforms moved = Frame();
  moved.camera_scene_position[0] += 0.001f;
  EXPECT_TRUE(SameFrame(Frame(), Frame()));
  EXPECT_FALSE(SameFrame(Frame(), moved));
}

TEST(FrameCachePolicy, SkyViewKeyIsTheCamerasRadiusAndSunZenithCosine) {
  SkyViewKey key = MakeSkyViewKey(Frame());
  EXPECT_FLOAT_EQ(key.r_m, kR + 100.0f);
  EXPECT_FLOAT_EQ(key.mu_s, 0.5f);
  // The view's direction is no part of it.
  FrameUniforms turned = Frame();
  turned.view_projection[0] = 2.0f;
  EXPECT_EQ(MakeSkyViewKey(turned), key);
}

TEST(FrameCachePolicy, SkyViewKeptWithinTenMetersAndTheSunsTolerance) {
  const SkyViewKey made{kR + 100.0f, 0.5f};
  EXPECT_FALSE(SkyViewReusable(std::nullopt, made, false)) << "the first frame makes it";
  EXPECT_TRUE(SkyViewReusable(made, made, false));
  EXPECT_TRUE(SkyViewReusable(made, made, true)) << "made for this very frame";
  EXPECT_TRUE(SkyViewReusable(made, {kR + 108.0f, 0.5f + 8e-6f}, false));
  EXPECT_FALSE(SkyViewReusable(made, {kR + 108.0f, 0.5f}, true)) << "an exact frame remakes a nearby one";
  EXPECT_FALSE(SkyViewReusable(made, {kR + 116.0f, 0.5f}, false)) << "16 m higher";
  EXPECT_FALSE(SkyViewReusable(made, {kR + 100.0f, 0.5f + 3e-5f}, false)) << "the sun moved";
}

// The bands a frame remakes, as the list of their indices.
std::vector<int> BandsRemade(const SkyViewLatticeKeys& made_for, const SkyViewKey& now, bool exact,
                             bool view_stopped = false) {
  std::array<bool, kSkyViewLatticeBands> remake = SkyViewLatticeBandsToRemake(made_for, now, exact, view_stopped);
  std::vector<int> bands;
  for (int b = 0; b < kSkyViewLatticeBands; ++b)
    if (remake[b]) bands.push_back(b);
  return bands;
}

SkyViewLatticeKeys AllBands(const SkyViewKey& key) {
  SkyViewLatticeKeys keys;
  keys.fill(key);
  return keys;
}

TEST(FrameCachePolicy, SkyViewLatticeBandsAreMadeAllAtOnceForAFarSunOrAnExactFrame) {
  const SkyViewKey made{kR + 100.0f, 0.5f};
  const std::vector<int> all = {0, 1, 2, 3, 4, 5, 6, 7};
  EXPECT_EQ(BandsRemade({}, made, false), all) << "the first frame";
  EXPECT_EQ(BandsRemade(AllBands(made), {kR + 100.0f, 0.5f + 1.01f * kSkyViewLatticeSunLag}, false), all)
      << "the sun moved beyond the lag allowed";
  EXPECT_EQ(BandsRemade(AllBands({kR + 100.0f, 0.05f}), {kR + 100.0f, 0.05f + 3e-5f}, false), all)
      << "a sun 3 degrees high moved";
  EXPECT_EQ(BandsRemade(AllBands(made), {kR + 105.0f, 0.5f}, true), all) << "an exact frame 5 m higher";
  EXPECT_TRUE(BandsRemade(AllBands(made), made, true).empty()) << "an exact frame of the same r and mu_s";
  SkyViewLatticeKeys one_behind = AllBands(made);
  one_behind[6] = SkyViewKey{kR + 130.0f, 0.5f};
  EXPECT_EQ(BandsRemade(one_behind, made, true), std::vector<int>{6});
}

TEST(FrameCachePolicy, SkyViewLatticeBandsFollowAClimbingCameraOneAFrame) {
  const SkyViewKey made{kR + 100.0f, 0.5f};
  EXPECT_TRUE(BandsRemade(AllBands(made), {kR + 109.0f, 0.5f}, false).empty()) << "within the table's 10 m";
  EXPECT_EQ(BandsRemade(AllBands(made), {kR + 130.0f, 0.5f}, false), std::vector<int>{0})
      << "all 30 m behind: the first of them";
  // A camera that climbs 12 m a frame: each frame remakes the band made longest ago.
  SkyViewLatticeKeys keys = AllBands(made);
  for (int frame = 1; frame <= 3; ++frame) {
    SkyViewKey now{kR + 100.0f + 12.0f * float(frame), 0.5f};
    std::vector<int> bands = BandsRemade(keys, now, false);
    ASSERT_EQ(bands.size(), 1u) << "frame " << frame;
    EXPECT_EQ(bands[0], frame - 1) << "frame " << frame;
    keys[bands[0]] = now;
  }
  // More than kSkyViewLatticeLagM behind: remade at once, and the most behind of the rest too.
  keys = AllBands(made);
  keys[5] = SkyViewKey{kR + 100.0f - kSkyViewLatticeLagM - 1.0f, 0.5f};
  keys[2] = SkyViewKey{kR + 120.0f, 0.5f};
  EXPECT_EQ(BandsRemade(keys, made, false), (std::vector<int>{2, 5})) << "5 is 51 m behind, 2 is 20 m ahead";
  keys[2] = made;
  EXPECT_EQ(BandsRemade(keys, made, false), std::vector<int>{5});
  keys[5] = SkyViewKey{kR + 100.0f - kSkyViewLatticeLagM + 1.0f, 0.5f};
  EXPECT_EQ(BandsRemade(keys, made, false), std::vector<int>{5}) << "49 m behind: the one most behind";
}

// A sun that moves 2e-4 a frame in mu_s, high enough for the bands to lag it: each frame remakes
// the band made longest ago, and a band that lags both the camera and the sun counts its larger lag.
TEST(FrameCachePolicy, SkyViewLatticeBandsFollowAMovingSunOneAFrame) {
  const SkyViewKey made{kR + 100.0f, 0.5f};
  EXPECT_TRUE(BandsRemade(AllBands(made), {kR + 100.0f, 0.5f + 0.9e-5f}, false).empty()) << "within the table's mu_s";
  SkyViewLatticeKeys keys = AllBands(made);
  for (int frame = 1; frame <= 3; ++frame) {
    SkyViewKey now{kR + 100.0f, 0.5f - 2e-4f * float(frame)};
    std::vector<int> bands = BandsRemade(keys, now, false);
    ASSERT_EQ(bands.size(), 1u) << "frame " << frame;
    EXPECT_EQ(bands[0], frame - 1) << "frame " << frame;
    keys[bands[0]] = now;
  }
  keys = AllBands(made);
  keys[3] = SkyViewKey{kR + 80.0f, 0.5f};  // 20 m behind: 0.4 of its limit
  keys[6] = SkyViewKey{kR + 100.0f, 0.5f + 0.5f * kSkyViewLatticeSunLag};
  EXPECT_EQ(BandsRemade(keys, made, false), std::vector<int>{6}) << "half the sun's limit behind";
  keys[3] = SkyViewKey{kR + 100.0f - 0.6f * kSkyViewLatticeLagM, 0.5f};
  EXPECT_EQ(BandsRemade(keys, made, false), std::vector<int>{3}) << "0.6 of the altitude's limit behind";
  EXPECT_EQ(BandsRemade(keys, made, false, true), (std::vector<int>{3, 6})) << "the view stopped";
  EXPECT_FALSE(SkyViewLatticeCaughtUp(keys, made));
}

TEST(FrameCachePolicy, SkyViewLatticeBandsOfAStoppedCameraAllCatchUpAtOnce) {
  const SkyViewKey made{kR + 100.0f, 0.5f};
  SkyViewLatticeKeys keys = AllBands(made);
  keys[1] = SkyViewKey{kR + 70.0f, 0.5f};
  keys[4] = SkyViewKey{kR + 85.0f, 0.5f};
  keys[6] = SkyViewKey{kR + 95.0f, 0.5f};
  EXPECT_EQ(BandsRemade(keys, made, false, true), (std::vector<int>{1, 4})) << "band 6 is within 10 m";
  EXPECT_EQ(BandsRemade(keys, made, false, false), std::vector<int>{1}) << "moving: the one most behind";
}

TEST(FrameCachePolicy, SkyViewLatticeCaughtUpWhenEveryBandIsWithinTheTablesTolerance) {
  const SkyViewKey made{kR + 100.0f, 0.5f};
  SkyViewLatticeKeys keys = AllBands(made);
  EXPECT_TRUE(SkyViewLatticeCaughtUp(keys, {kR + 109.0f, 0.5f}));
  keys[7] = SkyViewKey{kR + 80.0f, 0.5f};
  EXPECT_FALSE(SkyViewLatticeCaughtUp(keys, made)) << "band 7 is 20 m behind";
  EXPECT_FALSE(SkyViewLatticeCaughtUp({}, made)) << "none made";
}

TEST(FrameCachePolicy, FroxelsKeptForTheSameFrameUnderTheSameShadowMap) {
  FrameUniforms moved = Frame();
  moved.sun_direction[0] += 1e-4f;
  EXPECT_FALSE(FroxelsReusable(std::nullopt, Frame(), false)) << "none built yet";
  EXPECT_TRUE(FroxelsReusable(Frame(), Frame(), false));
  EXPECT_FALSE(FroxelsReusable(Frame(), Frame(), true)) << "the shadow map was redrawn";
  EXPECT_FALSE(FroxelsReusable(Frame(), moved, false)) << "the sun moved";
}

TEST(FrameCachePolicy, SunVisibilityReadBackOnlyForTheSameSurfacesUnderTheSameShadowMap) {
  const SunVisibilityKey written{Frame(), 4};
  FrameUniforms moved = Frame();
  moved.camera_scene_position[2] += 1.0f;
  EXPECT_FALSE(SunVisibilityReusable(std::nullopt, Frame(), 4, false)) << "none written yet";
  EXPECT_TRUE(SunVisibilityReusable(written, Frame(), 4, false));
  EXPECT_FALSE(SunVisibilityReusable(written, Frame(), 4, true)) << "the shadow map was redrawn";
  EXPECT_FALSE(SunVisibilityReusable(written, Frame(), 5, false)) << "other terrain chunks";
  EXPECT_FALSE(SunVisibilityReusable(written, moved, 4, false)) << "the camera moved";
}

TEST(FrameCachePolicy, SunVisibilityWrittenByFirstAndStillFramesOnly) {
  EXPECT_TRUE(SunVisibilityWorthCaching(/*first_frame=*/true, /*still_view=*/false));
  EXPECT_TRUE(SunVisibilityWorthCaching(false, true));
  EXPECT_FALSE(SunVisibilityWorthCaching(false, false)) << "a moving camera's frame";
}

ShadowKey Drawn() {
  ShadowKey key;
  for (int i = 0; i < kShadowCascades; ++i) {
    key.cascades[i].clip_from_world = glm::dmat4(double(i + 1));
    key.casters[i] = Chunks(i);
  }
  return key;
}

TEST(FrameCachePolicy, ShadowWindowsHeldExceptByAnExactFrame) {
  HeldCascades held = HeldShadowWindows(Drawn(), false);
  for (int i = 0; i < kShadowCascades; ++i) {
    ASSERT_TRUE(held[i].has_value());
    EXPECT_EQ(held[i]->clip_from_world, Drawn().cascades[i].clip_from_world);
  }
  for (const auto& window : HeldShadowWindows(Drawn(), true)) EXPECT_FALSE(window.has_value());
  for (const auto& window : HeldShadowWindows(std::nullopt, false)) EXPECT_FALSE(window.has_value());
}

TEST(FrameCachePolicy, ShadowWindowsMovedPerCascade) {
  ShadowCascades now = Drawn().cascades;
  for (bool moved : ShadowWindowsMoved(std::nullopt, now)) EXPECT_TRUE(moved) << "the first frame";
  for (bool moved : ShadowWindowsMoved(Drawn(), now)) EXPECT_FALSE(moved);
  now[1].clip_from_world[3][0] += 1.0;
  std::array<bool, kShadowCascades> moved = ShadowWindowsMoved(Drawn(), now);
  for (int i = 0; i < kShadowCascades; ++i) EXPECT_EQ(moved[i], i == 1) << "cascade " << i;
}

TEST(FrameCachePolicy, ShadowMapKeptByAStillWholeViewWithNoWindowMoved) {
  std::array<bool, kShadowCascades> none{}, one{};
  one[kShadowCascades - 1] = true;
  EXPECT_TRUE(ShadowMapKept(/*still_view=*/true, /*selection_whole=*/true, none, /*caught_up=*/true));
  EXPECT_FALSE(ShadowMapKept(false, true, none, true)) << "the view moved";
  EXPECT_FALSE(ShadowMapKept(true, false, none, true)) << "chunks were missing from the selection";
  EXPECT_FALSE(ShadowMapKept(true, true, one, true)) << "a window moved";
  EXPECT_FALSE(ShadowMapKept(true, true, none, false)) << "a tile lags the sun";
}

// Under a moving sun one tile a frame catches up, the one drawn for the sun farthest from this
// one (the nearest cascade on a tie); the others keep theirs. An exact frame and a first frame
// keep none, and a tile drawn for this sun has nothing to keep.
TEST(FrameCachePolicy, ShadowTilesCatchUpWithTheSunOneAFrame) {
  const glm::dvec3 sun = DirectionFromZenithAzimuth(80.0, 250.0);
  ShadowKey drawn = Drawn();
  for (ShadowCascade& c : drawn.cascades) c.toward_sun = sun;
  EXPECT_TRUE(ShadowTilesCaughtUp(drawn.cascades, sun));
  for (bool keep : ShadowTilesKeepingTheirSun(drawn, sun, false, 0.0)) EXPECT_FALSE(keep) << "nothing lags";

  const glm::dvec3 later = DirectionFromZenithAzimuth(81.0, 250.0);
  EXPECT_FALSE(ShadowTilesCaughtUp(drawn.cascades, later));
  std::array<bool, kShadowCascades> keep = ShadowTilesKeepingTheirSun(drawn, later, false, 0.0);
  for (int i = 0; i < kShadowCascades; ++i) EXPECT_EQ(keep[i], i != 0) << "a tie: the nearest first, cascade " << i;

  drawn.cascades[0].toward_sun = later;
  drawn.cascades[2].toward_sun = DirectionFromZenithAzimuth(79.0, 250.0);  // two degrees behind
  keep = ShadowTilesKeepingTheirSun(drawn, later, false, 0.0);
  EXPECT_FALSE(keep[0]) << "drawn for this sun";
  EXPECT_TRUE(keep[1]);
  EXPECT_FALSE(keep[2]) << "the farthest behind";
  EXPECT_TRUE(keep[3]);
  for (bool k : ShadowTilesKeepingTheirSun(drawn, later, /*exact=*/true, 0.0)) EXPECT_FALSE(k) << "an exact frame";
  for (bool k : ShadowTilesKeepingTheirSun(std::nullopt, later, false, 0.0)) EXPECT_FALSE(k) << "the first frame";
}

// The default view's tiles, in metres: texels from 14 cm to 206 m (shadow_cascades.h), and depth
// ranges from the slice's far side to the casters' top.
ShadowKey DrawnAtTheDefaultView(const glm::dvec3& sun) {
  ShadowKey drawn = Drawn();
  const std::array<double, kShadowCascades> texels = {0.14, 1.6, 18.0, 206.0}, depths = {3.5e3, 4e3, 12e3, 130e3};
  for (int i = 0; i < kShadowCascades; ++i) {
    drawn.cascades[i].toward_sun = sun;
    drawn.cascades[i].texel_m = texels[i];
    drawn.cascades[i].depth_max_m = depths[i];
  }
  return drawn;
}

// A sun turned by an angle a moves the shadows by a times the reach, or the tile's depth range
// where shorter, counted in the tile's texels.
TEST(FrameCachePolicy, SunLagCountsTheShadowsMoveInTexels) {
  ShadowCascade tile{.depth_min_m = 1000.0, .depth_max_m = 6000.0, .texel_m = 2.0, .toward_sun = {0.0, 0.0, 1.0}};
  const glm::dvec3 turned(std::sin(1e-3), 0.0, std::cos(1e-3));
  EXPECT_NEAR(SunLagTexels(tile, turned, 1000.0), 0.5, 1e-9);
  EXPECT_NEAR(SunLagTexels(tile, turned, 1e6), 2.5, 1e-9) << "the depth range is the shorter";
  EXPECT_EQ(SunLagTexels(tile, tile.toward_sun, 1000.0), 0.0);
}

// The reach against a march along the ray from the lowest receiver until it passes the casters'
// top, at a high sun, a low one, and one at the horizon (where the curvature's allowance over
// kShadowFarM is what makes it finite: the ray starts 0.9 degrees up).
TEST(FrameCachePolicy, ShadowReachIsTheRayFromTheLowestReceiverToTheCastersTop) {
  const double R = 6360e3;
  const CasterBounds casters{.top_radius_m = R + 3300.0, .bottom_radius_m = R - 10.0};
  const glm::dvec3 up(0.0, 0.0, 1.0);
  for (double elevation_deg : {60.0, 11.0, 0.0}) {
    const double e = glm::radians(elevation_deg) - kShadowFarM / casters.bottom_radius_m;
    const glm::dvec2 start(0.0, casters.bottom_radius_m), direction(std::cos(e), std::sin(e));
    double s = 0.0;
    while (glm::length(start + s * direction) < casters.top_radius_m) s += 1.0;
    const glm::dvec3 sun(std::cos(glm::radians(elevation_deg)), 0.0, std::sin(glm::radians(elevation_deg)));
    EXPECT_NEAR(ShadowReachM(sun, up, casters), s, 1.0) << elevation_deg;
  }
}

// While the sun moves, tiles whose shadows moved less than half a texel keep their sun and wait:
// the sun turned by 0.02 degrees at 30 degrees up moves the shadows of a 6.6 km reach by 2.3 m,
// 16 texels of the first tile and 0.011 of the last. The most behind of the others catches up
// (all are as far behind in angle: the nearest). A still view lets none wait.
TEST(FrameCachePolicy, ASlowSunLeavesTilesWithinHalfATexel) {
  const glm::dvec3 sun = DirectionFromZenithAzimuth(60.0, 250.0), later = DirectionFromZenithAzimuth(60.02, 250.0);
  const ShadowKey drawn = DrawnAtTheDefaultView(sun);
  const double reach = 6.6e3;
  std::array<bool, kShadowCascades> keep = ShadowTilesKeepingTheirSun(drawn, later, false, reach);
  EXPECT_FALSE(keep[0]) << "16 texels behind: catches up";
  for (int i = 1; i < kShadowCascades; ++i) EXPECT_TRUE(keep[i]) << "cascade " << i;
  EXPECT_GT(SunLagTexels(drawn.cascades[1], later, reach), kSunLagToleranceTexels) << "behind, waiting for its turn";
  EXPECT_LT(SunLagTexels(drawn.cascades[2], later, reach), kSunLagToleranceTexels);

  ShadowKey caught_up_near = drawn;
  caught_up_near.cascades[0].toward_sun = later;
  keep = ShadowTilesKeepingTheirSun(caught_up_near, later, false, reach);
  EXPECT_FALSE(keep[1]) << "the second tile's turn";
  EXPECT_TRUE(keep[2] && keep[3]) << "within half a texel";
  keep = ShadowTilesKeepingTheirSun(caught_up_near, later, false, 0.0);
  EXPECT_FALSE(keep[1]) << "a still view: the next one catches up";
  caught_up_near.cascades[1].toward_sun = later;
  keep = ShadowTilesKeepingTheirSun(caught_up_near, later, false, reach);
  EXPECT_TRUE(keep[2] && keep[3]) << "nothing to catch up while the sun moves";
  keep = ShadowTilesKeepingTheirSun(caught_up_near, later, false, 0.0);
  EXPECT_FALSE(keep[2]) << "a still view catches up the rest, the nearest first";
  EXPECT_TRUE(keep[3]);
}

TEST(FrameCachePolicy, CastersKeptWithinTheSelectionsSlack) {
  terrain::LodView view;
  view.camera = {10.0, 20.0, 300.0};
  view.pixels_per_radian = 870.0;
  view.max_error_px = 4.0;
  ShadowCascade cascade;
  cascade.planes[0] = {1.0, 0.0, 0.0, -5.0};
  const std::optional<CasterSelection> made =
      MakeCasterSelection(view, cascade, CascadeCasters{.deferred = 0, .camera_slack_m = 2.0});
  terrain::LodView now = view;
  now.camera += glm::dvec3(1.2, -1.2, 0.9);  // 1.9 m away
  EXPECT_TRUE(CastersKept(made, now, cascade, /*moved=*/false));
  EXPECT_FALSE(CastersKept(made, now, cascade, true)) << "the window moved";
  EXPECT_FALSE(CastersKept(MakeCasterSelection(view, cascade, CascadeCasters{.deferred = 3, .camera_slack_m = 2.0}),
                           now, cascade, false))
      << "chunks were missing from the selection";
  EXPECT_FALSE(CastersKept(std::nullopt, now, cascade, false)) << "no terrain was selected";
  now.camera = view.camera + glm::dvec3(0.0, 0.0, 2.0);
  EXPECT_FALSE(CastersKept(made, now, cascade, false)) << "as far as the slack";
  now = view;
  now.pixels_per_radian = 900.0;
  EXPECT_FALSE(CastersKept(made, now, cascade, false)) << "another field of view";
  now = view;
  now.max_error_px = 2.0;
  EXPECT_FALSE(CastersKept(made, now, cascade, false)) << "another error bound";
  ShadowCascade other = cascade;
  other.planes[0].w = -6.0;
  EXPECT_FALSE(CastersKept(made, view, other, false)) << "another cascade box";
}

TEST(FrameCachePolicy, TerrainSelectionKeptForTheSameViewWhenItLackedNoChunk) {
  EXPECT_TRUE(TerrainSelectionKept(/*same_lod_view=*/true, /*selection_whole=*/true));
  EXPECT_FALSE(TerrainSelectionKept(false, true)) << "the camera moved";
  EXPECT_FALSE(TerrainSelectionKept(true, false)) << "chunks were missing from the selection";
}

TEST(FrameCachePolicy, ShadowTileRedrawnWhenItsWindowOrCastersChanged) {
  EXPECT_FALSE(ShadowTileRedrawn(false, Chunks(2), Chunks(2)));
  EXPECT_TRUE(ShadowTileRedrawn(true, Chunks(2), Chunks(2))) << "its window moved";
  EXPECT_TRUE(ShadowTileRedrawn(false, Chunks(3), Chunks(2))) << "its casters changed";
}

}  // namespace
}  // namespace aerial
