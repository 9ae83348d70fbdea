#include "aerial/render/frame_cache_policy.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace aerial {

bool SameFrame(const FrameUniforms& a, const FrameUniforms& b) {
  return std::memcmp(&a, &b, sizeof(FrameUniforms)) == 0;
}

SkyViewKey MakeSkyViewKey(const FrameUniforms& frame) {
  const auto& p = frame.camera_planet_position;
  const auto& s = frame.sun_direction;
  float r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  return {r, (p[0] * s[0] + p[1] * s[1] + p[2] * s[2]) / r};
}

namespace {

constexpr float kSkyViewAltitudeToleranceM = 10.0f, kSkyViewMuSTolerance = 1e-5f;

// How far (m) a table or band made for `made_for` lags `now` in altitude; infinite when it was
// never made or the sun moved beyond the tolerance.
float AltitudeLag(const std::optional<SkyViewKey>& made_for, const SkyViewKey& now) {
  if (!made_for || std::fabs(made_for->mu_s - now.mu_s) > kSkyViewMuSTolerance) return INFINITY;
  return std::fabs(made_for->r_m - now.r_m);
}

// How far a lattice band made for `made_for` lags `now`, as the larger of its altitude's and its
// sun's lag, each a fraction of what a moving view allows (kSkyViewLatticeLagM,
// kSkyViewLatticeSunLag, none under a low sun); 0 within the table's own tolerances, infinite when
// it was never made.
float BandLag(const std::optional<SkyViewKey>& made_for, const SkyViewKey& now) {
  if (!made_for) return INFINITY;
  const float altitude = std::fabs(made_for->r_m - now.r_m), sun = std::fabs(made_for->mu_s - now.mu_s);
  if (altitude <= kSkyViewAltitudeToleranceM && sun <= kSkyViewMuSTolerance) return 0.0f;
  const bool sun_high = std::min(made_for->mu_s, now.mu_s) >= kSkyViewLatticeSunLagMinMuS;
  const float sun_lag = sun <= kSkyViewMuSTolerance ? 0.0f : sun_high ? sun / kSkyViewLatticeSunLag : INFINITY;
  return std::max(altitude / kSkyViewLatticeLagM, sun_lag);
}

}  // namespace

bool SkyViewReusable(const std::optional<SkyViewKey>& made_for, const SkyViewKey& now, bool exact) {
  if (made_for == now) return true;
  return !exact && AltitudeLag(made_for, now) <= kSkyViewAltitudeToleranceM;
}

std::array<bool, kSkyViewLatticeBands> SkyViewLatticeBandsToRemake(const SkyViewLatticeKeys& made_for,
                                                                    const SkyViewKey& now, bool exact,
                                                                    bool view_stopped) {
  std::array<bool, kSkyViewLatticeBands> remake{};
  int most_behind = -1;
  float most_lag = 0.0f;
  for (int b = 0; b < kSkyViewLatticeBands; ++b) {
    float lag = BandLag(made_for[b], now);
    remake[b] = lag > (view_stopped ? 0.0f : 1.0f) || (exact && made_for[b] != now);
    if (!remake[b] && lag > most_lag) {
      most_lag = lag;
      most_behind = b;
    }
  }
  if (most_behind >= 0) remake[most_behind] = true;
  return remake;
}

bool SkyViewLatticeCaughtUp(const SkyViewLatticeKeys& made_for, const SkyViewKey& now) {
  return std::all_of(made_for.begin(), made_for.end(),
                     [&](const std::optional<SkyViewKey>& band) { return BandLag(band, now) == 0.0f; });
}

bool FroxelsReusable(const std::optional<FrameUniforms>& built_for, const FrameUniforms& now,
                     bool shadow_map_updated) {
  return built_for && !shadow_map_updated && SameFrame(*built_for, now);
}

bool SunVisibilityReusable(const std::optional<SunVisibilityKey>& written_for, const FrameUniforms& frame,
                           uint64_t terrain, bool shadow_map_updated) {
  return written_for && !shadow_map_updated && written_for->terrain == terrain && SameFrame(written_for->frame, frame);
}

bool SunVisibilityWorthCaching(bool first_frame, bool still_view) { return first_frame || still_view; }

HeldCascades HeldShadowWindows(const std::optional<ShadowKey>& drawn, bool exact) {
  HeldCascades held;
  if (drawn && !exact)
    for (int i = 0; i < kShadowCascades; ++i) held[i] = drawn->cascades[i];
  return held;
}

std::array<bool, kShadowCascades> ShadowWindowsMoved(const std::optional<ShadowKey>& drawn,
                                                     const ShadowCascades& now) {
  std::array<bool, kShadowCascades> moved{};
  for (int i = 0; i < kShadowCascades; ++i)
    moved[i] = !drawn || drawn->cascades[i].clip_from_world != now[i].clip_from_world;
  return moved;
}

bool TerrainSelectionKept(bool same_lod_view, bool selection_whole) { return same_lod_view && selection_whole; }

double ShadowReachM(const glm::dvec3& sun, const glm::dvec3& up, const CasterBounds& casters) {
  const double r = casters.bottom_radius_m, top = casters.top_radius_m;
  const double elevation = std::asin(std::clamp(glm::dot(sun, up), -1.0, 1.0)) - kShadowFarM / r;
  // The ray from radius r at elevation e meets radius `top` after -r sin e + sqrt(top^2 - r^2 cos^2 e).
  const double mu = std::sin(elevation);
  return -r * mu + std::sqrt(std::max(top * top - r * r * (1.0 - mu * mu), 0.0));
}

double SunLagTexels(const ShadowCascade& tile, const glm::dvec3& sun, double reach_m) {
  const double angle = std::acos(std::clamp(glm::dot(tile.toward_sun, sun), -1.0, 1.0));
  return angle * std::min(reach_m, tile.depth_max_m - tile.depth_min_m) / tile.texel_m;
}

std::array<bool, kShadowCascades> ShadowTilesKeepingTheirSun(const std::optional<ShadowKey>& drawn,
                                                             const glm::dvec3& sun, bool exact,
                                                             double moving_sun_reach_m) {
  std::array<bool, kShadowCascades> keep{};
  if (!drawn || exact) return keep;
  int most_behind = -1;
  double lowest_cosine = 2.0;  // of the angle between a tile's sun and this one
  for (int i = 0; i < kShadowCascades; ++i) {
    const ShadowCascade& tile = drawn->cascades[i];
    const glm::dvec3& drawn_for = tile.toward_sun;
    if (drawn_for == sun) continue;
    keep[i] = true;
    if (moving_sun_reach_m > 0.0 && SunLagTexels(tile, sun, moving_sun_reach_m) < kSunLagToleranceTexels) continue;
    if (double cosine = glm::dot(drawn_for, sun); cosine < lowest_cosine) {
      lowest_cosine = cosine;
      most_behind = i;
    }
  }
  if (most_behind >= 0) keep[most_behind] = false;
  return keep;
}

bool ShadowTilesCaughtUp(const ShadowCascades& cascades, const glm::dvec3& sun) {
  return std::all_of(cascades.begin(), cascades.end(), [&](const ShadowCascade& c) { return c.toward_sun == sun; });
}

bool ShadowMapKept(bool still_view, bool selection_whole, const std::array<bool, kShadowCascades>& moved,
                   bool caught_up) {
  return still_view && selection_whole && caught_up && std::find(moved.begin(), moved.end(), true) == moved.end();
}

CasterSelection MakeCasterSelection(const terrain::LodView& view, const ShadowCascade& cascade,
                                    const CascadeCasters& selected) {
  return {.camera = view.camera,
          .pixels_per_radian = view.pixels_per_radian,
          .max_error_px = view.max_error_px,
          .planes = cascade.planes,
          .camera_slack_m = selected.camera_slack_m,
          .whole = selected.deferred == 0};
}

bool CastersKept(const std::optional<CasterSelection>& made, const terrain::LodView& now,
                 const ShadowCascade& cascade, bool moved) {
  if (moved || !made || !made->whole) return false;
  if (made->pixels_per_radian != now.pixels_per_radian || made->max_error_px != now.max_error_px) return false;
  return made->planes == cascade.planes && glm::length(now.camera - made->camera) < made->camera_slack_m;
}

bool ShadowTileRedrawn(bool moved, const std::vector<terrain::SelectedChunk>& casters,
                       const std::vector<terrain::SelectedChunk>& drawn) {
  return moved || casters != drawn;
}

}  // namespace aerial
