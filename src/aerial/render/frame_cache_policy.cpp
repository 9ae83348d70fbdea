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

bool SkyViewReusable(const std::optional<SkyViewKey>& made_for, const SkyViewKey& now, bool exact) {
  constexpr float kAltitudeToleranceM = 10.0f, kMuSTolerance = 1e-5f;
  if (!made_for) return false;
  bool close = std::fabs(made_for->r_m - now.r_m) <= kAltitudeToleranceM &&
               std::fabs(made_for->mu_s - now.mu_s) <= kMuSTolerance;
  return *made_for == now || (close && !exact);
}

bool FroxelsReusable(const std::optional<FrameUniforms>& built_for, const FrameUniforms& now,
                     bool shadow_map_updated) {
  return built_for && !shadow_map_updated && SameFrame(*built_for, now);
}

bool SunVisibilityReusable(const std::optional<SunVisibilityKey>& written_for, const FrameUniforms& frame,
                           const std::vector<terrain::SelectedChunk>& chunks, bool shadow_map_updated) {
  return written_for && !shadow_map_updated && written_for->chunks == chunks && SameFrame(written_for->frame, frame);
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

bool ShadowMapKept(bool still_view, bool selection_whole, const std::array<bool, kShadowCascades>& moved) {
  return still_view && selection_whole && std::find(moved.begin(), moved.end(), true) == moved.end();
}

bool ShadowTileRedrawn(bool moved, const std::vector<terrain::SelectedChunk>& casters,
                       const std::vector<terrain::SelectedChunk>& drawn) {
  return moved || casters != drawn;
}

}  // namespace aerial
