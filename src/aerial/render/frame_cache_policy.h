#pragma once
// What a frame may reuse of what earlier frames made (the sky-view table, the froxel volume, the
// screen's sun visibility, the shadow map's tiles), decided from what each was made for (its key)
// and this frame's: pure functions, so that each rule is tested without a GPU
// (frame_cache_policy_test.cpp). The renderer keeps the keys and records what these leave to redo.
#include <array>
#include <optional>
#include <vector>

#include "aerial/render/shadow_cascades.h"
#include "aerial/render/shadow_terrain.h"
#include "aerial/render/sky_view_layout.h"
#include "aerial/shader_abi/frame_block.h"
#include "aerial/terrain/lod_selection.h"

namespace aerial {

// Two frame blocks are the same view under the same sun: equal to the bit.
bool SameFrame(const FrameUniforms& a, const FrameUniforms& b);

// ---- The sky-view table ----
// It depends on the camera's distance from the planet's center and the sun's zenith angle there,
// nothing else (sky_view.glsl builds it in the camera's local frame).
struct SkyViewKey {
  float r_m = 0.0f, mu_s = 0.0f;
  bool operator==(const SkyViewKey&) const = default;
};
SkyViewKey MakeSkyViewKey(const FrameUniforms& frame);
// A table is remade on the first frame, when the sun moves (mu_s by more than 1e-5, 1/80 of the
// sun's radius at the horizon), and when the camera's altitude moves by more than 10 m. A table
// 10 m off changes the frame by at most 0.07% relative RMSE (sunset, 30 m to 3 km up; 0.02% at
// noon; measured against a fresh table when this was chosen, and tested), well under the 0.2-0.8%
// that the table itself differs from the per-pixel sky; a camera climbing at 180 m/s remakes it
// every other frame instead of every frame. An exact frame (Renderer::Record's `complete`) remakes
// any table not made for its own r and mu_s.
bool SkyViewReusable(const std::optional<SkyViewKey>& made_for, const SkyViewKey& now, bool exact);

// ---- The sky-view table's correction lattice ----
// The correction at the lattice's nodes (sky_view_correction.comp) is most of the cost of remaking
// the table: it marches six suns along each of 1,862 rays, about 30 ms of process CPU of the
// moving-camera frame on lavapipe (noon). It changes far more slowly with the camera's altitude
// and the sun's angle than the table's texels do, so its rows are made in kSkyViewLatticeBands
// bands, each for the altitude and the sun of its own frame, and a climbing camera or a moving sun
// remakes one band a frame, the one that lags most, instead of all eight: time-sliced, as engines
// update their sky and probe captures.
//  - A band may lag the camera by up to kSkyViewLatticeLagM. With the whole lattice 49 m behind and
//    the table's texels remade, the frame moved by at most 0.069% relative RMSE (twilight 1 km up;
//    sunset 0.019%, noon 0.006%; tested), less than the table's own 10 m tolerance moves it
//    (0.09% at sunset, 0.35% at twilight). At 99 m it was 0.087% at sunset, 0.11% at twilight.
//  - A band may lag the sun by up to kSkyViewLatticeSunLag in mu_s (1.6 degrees of a sun 20
//    degrees from the zenith, 0.6 of one 80 degrees from it) while the sun is at least
//    kSkyViewLatticeSunLagMinMuS high (6 degrees above the horizon) for the band and the frame:
//    with seven bands of eight 0.0095 behind and the table's texels remade, the frame moved by at
//    most 0.070% relative RMSE (noon; 0.015% in the evening, 80 degrees; tested), within the 0.1%
//    the camera's lag is held to. A sun moving half a degree a frame (the viewer's arrow keys, the
//    sun sweep) so remakes about half the bands a frame, where a limit of 0.002 (0.015% at noon)
//    would have it remake all eight every frame. A lower sun's Earth shadow crosses the view: 0.0002
//    behind, a sun 1 degree below the horizon moved the frame by 0.13%, so a band is remade at
//    once there.
//  - A band whose lag, in altitude or sun, is beyond its limit is remade at once, and so is every
//    band on the first frame, and in an exact frame not made for its own r and mu_s, as the table is.
//  - A band within the table's tolerances (10 m, mu_s 1e-5) is left as it is.
//  - A view that stopped (the same frame as the one before: camera and sun) remakes every band
//    beyond those tolerances at once, so that the view settles in one frame, as it did with a whole
//    lattice.
// The table's texels are remade after any band is (the renderer's SkyViewStale).
inline constexpr float kSkyViewLatticeLagM = 50.0f;
inline constexpr float kSkyViewLatticeSunLag = 1e-2f, kSkyViewLatticeSunLagMinMuS = 0.1f;
using SkyViewLatticeKeys = std::array<std::optional<SkyViewKey>, kSkyViewLatticeBands>;
std::array<bool, kSkyViewLatticeBands> SkyViewLatticeBandsToRemake(const SkyViewLatticeKeys& made_for,
                                                                    const SkyViewKey& now, bool exact,
                                                                    bool view_stopped);
// Whether every band is within the table's tolerances of `now` (nothing is left for later frames).
bool SkyViewLatticeCaughtUp(const SkyViewLatticeKeys& made_for, const SkyViewKey& now);

// ---- The terrain's chunks ----
// A frame keeps the chunks its last frame selected when its level-of-detail view is the same and
// that selection lacked none: the same view and rule over the same built chunks select the same
// ones, occlusion culling included (terrain/lod_selection.h). A still camera (under a moving sun
// too) then spends no CPU on the terrain.
bool TerrainSelectionKept(bool same_lod_view, bool selection_whole);

// ---- The froxel volume ----
// It depends on the camera, the sun, the shadow map and the tables only: a still view under an
// unchanged shadow map keeps it.
bool FroxelsReusable(const std::optional<FrameUniforms>& built_for, const FrameUniforms& now,
                     bool shadow_map_updated);

// ---- The screen's sun visibility (opaque_fragment.glsl) ----
// What the frame that wrote it showed.
struct SunVisibilityKey {
  FrameUniforms frame;
  uint64_t terrain = 0;  // the renderer's count of the changes of the terrain chunks it draws
};
// A frame may read what the last caching frame wrote when it draws the same surfaces (its uniforms,
// so the camera and the sun, and its terrain chunks are that frame's) under the same shadow map.
bool SunVisibilityReusable(const std::optional<SunVisibilityKey>& written_for, const FrameUniforms& frame,
                           uint64_t terrain, bool shadow_map_updated);
// Whether a frame that looks the sun visibility up also writes it for the next frames: the write
// is a second color target and a raster scope of its own, which only a next frame of the same
// view reads. So a renderer's first frame writes it (a still image, or a view about to stay), and
// so does a frame whose view is the one before it (the camera stopped); a moving camera's frames
// do not.
bool SunVisibilityWorthCaching(bool first_frame, bool still_view);

// ---- The shadow map's tiles ----
// The terrain selection that a tile's casters came from (SelectCascadeCasters): what it depends on
// (the camera, the level-of-detail rule, the cascade's box), how far its camera may move before
// it would pick other chunks, and whether it lacked none.
struct CasterSelection {
  glm::dvec3 camera{0.0};
  double pixels_per_radian = 0.0, max_error_px = 0.0;
  std::array<glm::dvec4, 5> planes{};
  double camera_slack_m = 0.0;
  bool whole = false;
};
CasterSelection MakeCasterSelection(const terrain::LodView& view, const ShadowCascade& cascade,
                                    const CascadeCasters& selected);

// What the tiles show: the cascades' windows and the terrain chunks drawn in them.
struct ShadowKey {
  ShadowCascades cascades;
  ShadowTerrain casters;
  std::array<std::optional<CasterSelection>, kShadowCascades> selections;  // none without terrain
};
// The windows a frame's fit keeps (shadow_cascades.h): those the map holds, except for an exact
// frame, which fits its windows afresh as a new renderer would.
HeldCascades HeldShadowWindows(const std::optional<ShadowKey>& drawn, bool exact);
// Per cascade, whether its window moved (every one on the first frame).
std::array<bool, kShadowCascades> ShadowWindowsMoved(const std::optional<ShadowKey>& drawn,
                                                     const ShadowCascades& now);
// How far along a sun ray (m) a caster may lie from a point whose shadow it is: from the lowest
// point that reads the map to the casters' top (CasterBounds), with the sun at its lowest over
// the points the map covers (its elevation over the camera's horizon, up: the camera's vertical,
// less the planet's curvature across kShadowFarM). Only points below the casters' top read the
// map (shadow.glsl).
double ShadowReachM(const glm::dvec3& sun, const glm::dvec3& up, const CasterBounds& casters);
// How far a tile's shadows may have moved since it was drawn, in its own texels: a sun turned by
// an angle a moves a caster's shadow across the light's axes by at most a times the caster's
// distance along the ray, which is within the reach and the tile's depth range.
double SunLagTexels(const ShadowCascade& tile, const glm::dvec3& sun, double reach_m);
// Shadows that moved less than this are still the sun's: below the lookup's 3x3-texel filter.
inline constexpr double kSunLagToleranceTexels = 0.5;
// A moving sun: each tile is drawn for the sun of its own frame (its cascade's light axes go to
// the shaders with it, shader_abi/shadow_block.h), and when the sun moves the tiles catch up one a
// frame, the one whose sun lags the most first (the nearest on a tie), as engines time-slice the
// updates of their cascades: a frame under a moving sun redraws one tile instead of all four.
// While the sun keeps moving (moving_sun_reach_m > 0: ShadowReachM), a tile whose shadows moved
// less than kSunLagToleranceTexels of its texels is not behind: it keeps its sun and waits. A slow
// sun so redraws the near tiles, whose texels are centimetres, and seldom the far ones, whose
// texels are 200 m and whose terrain is the dearest to draw. Each tile lags by at most three
// frames' motion or half a texel; once the sun stops (a still view, moving_sun_reach_m = 0) every
// tile catches up, three frames later at most (a still view keeps drawing until then:
// FrameInfo::settled), so a still view becomes the exact frame.
// Per cascade, whether its held window may keep the sun it was drawn for this frame
// (FitShadowCascades' keep_held_sun): all but the one that catches up. An exact frame keeps none.
std::array<bool, kShadowCascades> ShadowTilesKeepingTheirSun(const std::optional<ShadowKey>& drawn,
                                                             const glm::dvec3& sun, bool exact,
                                                             double moving_sun_reach_m);
// Whether every tile was drawn for this sun.
bool ShadowTilesCaughtUp(const ShadowCascades& cascades, const glm::dvec3& sun);
// A still view whose terrain selection lacked no chunk, with no window moved and no tile behind
// the sun, draws what the map holds without selecting its casters again.
bool ShadowMapKept(bool still_view, bool selection_whole, const std::array<bool, kShadowCascades>& moved,
                   bool caught_up);
// A frame of a moving camera keeps a tile too, without selecting its terrain casters again, when
// its window did not move and its last selection lacked no chunk and would pick the same chunks for
// this frame: the same box and level-of-detail rule, and the camera closer than the selection's
// slack (terrain::Selection::camera_slack_m) to where it was made (a window that did not move has
// the same texel, so the cascade resolves the same error). The tile would then get its drawn
// casters again, so it would not be redrawn. The first cascade resolves every level and keeps its
// casters for a metre or two of travel; the far ones, coarser, for tens of metres.
bool CastersKept(const std::optional<CasterSelection>& made, const terrain::LodView& now,
                 const ShadowCascade& cascade, bool moved);
// A tile is redrawn when its window moved or its terrain casters changed (the camera's level of
// detail changed, or chunks deferred for the build budget arrived). The scene's meshes are fixed
// for the renderer's life.
bool ShadowTileRedrawn(bool moved, const std::vector<terrain::SelectedChunk>& casters,
                       const std::vector<terrain::SelectedChunk>& drawn);

}  // namespace aerial
