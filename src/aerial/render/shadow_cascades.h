#pragma once
// The sun's shadow map fitted to the camera: cascaded shadow maps (Engel, "Cascaded Shadow Maps",
// ShaderX5, 2006; Zhang et al., "Parallel-Split Shadow Maps", 2006). The view frustum is cut
// into kShadowCascades slices of view depth, each covered by its own orthographic projection from
// the sun, so that a texel near the camera covers centimeters and one of the last cascade still
// reaches the mountains 85 km away.
//
// The fits are stable (Valient, "Stable Rendering of Cascaded Shadow Maps", ShaderX6, 2008): each
// slice is bounded by a sphere, whose radius depends only on the slice, the field of view and
// the aspect (not on where the camera looks, so the texel size never changes as the camera
// turns), and the sphere's centre is snapped to whole texels along the light's axes, which are
// fixed by the sun alone. A world point then falls on the same texel grid whatever the camera
// does: the shadow's edges do not crawl or shimmer as it moves and turns, and a small move leaves
// the fit, and so the cached shadow map (shadow_map.h), unchanged.
//
// Each cascade's window is also wider than its slice by kShadowWindowSlack, and a window the
// shadow map already holds is kept for as long as its slice still fits inside it (the "held"
// cascades of FitShadowCascades): a camera that moves or turns by less than the slack keeps every
// tile of the shadow map, and a tile is redrawn only when its own slice leaves it (the pattern of
// "scrolling" or "cached" cascades in game engines, e.g. Unreal's virtual shadow map page cache,
// here one window per cascade). Each kept window keeps its texel grid: no shimmer either way.
//
// Pure CPU math in double precision, in the scene frame (scene.h); shadow_cascades_test checks it.
#include <array>
#include <optional>

#include <glm/glm.hpp>

#include "aerial/scene.h"
#include "aerial/shader_abi/shadow_block.h"

namespace aerial {

// Texels around each slice's bounding square that still belong to its tile: the lookup's reach
// from any point of the slice (its filter and its offset along the normal,
// shaders/include/shadow.glsl), plus one. So a lookup picks its cascade by view depth alone.
inline constexpr int kShadowMarginTexels = 4;

// The view depths (m) that split the frustum: the first cascade ends at kFirstShadowSplitM and
// the last at kShadowFarM (the terrain's edge, kTerrainRadiusM); the splits between grow
// geometrically (the "logarithmic" split of Zhang et al., which keeps the ratio of a texel's size
// to its distance the same in every cascade): 60 m, 700 m, 8.1 km, 100 km.
inline constexpr double kFirstShadowSplitM = 60.0;
inline constexpr double kShadowFarM = 100e3;

// Everything that casts a shadow lies within this sphere (scene frame): the light's depth range
// reaches from each cascade to the sphere's sun-facing side.
struct CasterBounds {
  glm::dvec3 center{0.0};
  double radius_m = 0.0;
  // The largest distance of a caster from the planet's centre: the air above it is in the sun
  // wherever the sun is above the local horizon (shadow.glsl, SunVisibilityOnRay).
  double top_radius_m = 0.0;
  // The smallest distance from the planet's centre of a point that reads the map: the ground,
  // the terrain's lowest hollow and the meshes' lowest vertex.
  double bottom_radius_m = 0.0;
};

// How much wider than its slice's bounding sphere a cascade's window is, as a fraction of the
// sphere's radius: the slice may drift this far (along any light axis) before the window must
// move. 0.25 coarsens the texels by 25% (the first cascade's from 11 to 14 cm) and keeps the
// first cascade's window through 14 m of camera travel. The last cascade's window is over 200 km
// wide and the terrain it draws grows with its area, so it gets 0.1: 9.5 km of travel, or about 4
// degrees of turn, at 10% coarser texels.
inline constexpr std::array<double, kShadowCascades> kShadowWindowSlack = {0.25, 0.25, 0.25, 0.1};

struct CascadeFitInput {
  Camera camera;
  double aspect = 16.0 / 9.0;
  glm::dvec3 sun{0.0, 0.0, 1.0};  // unit vector toward the sun
  int tile_texels = 1024;          // the width and height of one cascade's depth map
  CasterBounds casters;
};

// The light's axes, fixed by the sun alone: right and up span the depth map, toward_sun is depth.
struct LightBasis {
  glm::dvec3 right, up, toward_sun;
};
LightBasis MakeLightBasis(const glm::dvec3& sun);

struct ShadowCascade {
  double near_m = 0.0, far_m = 0.0;  // the slice of view depth it was fitted to
  // The bounding sphere's snapped centre in light coordinates (dot with right, up, toward_sun)
  // and its radius; the depth map spans centre.xy +- radius.
  glm::dvec3 center_light{0.0};
  double radius_m = 0.0;
  // Light depths (m along toward_sun) of depth 0 (the sphere's far side) and depth 1 (the
  // casters' sun-facing side).
  double depth_min_m = 0.0, depth_max_m = 0.0;
  double texel_m = 0.0;  // the world size of one texel of the depth map
  // Scene frame -> clip: x and y in [-1, 1] over the depth map, depth in [0, 1], 1 toward the sun
  // (reversed, as the camera's depth: the nearest caster has the largest value).
  glm::dmat4 clip_from_world{1.0};
  // Where the tile's casters are drawn, in light coordinates across (x, y): the slice's own
  // footprint (its corners' bounding rectangle), widened by the slack and held with the window.
  // Only a caster on a sun ray through the slice shades it, so the tile needs none outside (at
  // the default view the last tile draws 1780 chunks in it where its whole square held 1964).
  glm::dvec2 casters_min{0.0}, casters_max{0.0};
  // The box of those casters, as LodView planes (terrain/lod_selection.h): a point p is inside
  // when dot(plane.xyz, p) + plane.w >= 0 for the four sides and the far side (away from the sun).
  std::array<glm::dvec4, 5> planes{};
  // What the window was fitted for: the sun, its slice's bounding sphere radius and the casters'
  // top along the sun; a held window is kept only for the same slice and casters, and for the
  // same sun unless FitShadowCascades is allowed to keep the sun it was drawn for.
  glm::dvec3 toward_sun{0.0};
  double slice_radius_m = 0.0;
  double casters_top_m = 0.0;
  // How far the slice has drifted inside its window, as a fraction of the slack: 0 just after a
  // fit, 1 at the window's edge (beyond it the window is fitted anew).
  double drift = 0.0;
};

using ShadowCascades = std::array<ShadowCascade, kShadowCascades>;
// The cascades a shadow map holds, per cascade (nullopt: none, or one to fit anew).
using HeldCascades = std::array<std::optional<ShadowCascade>, kShadowCascades>;

// The view depth at which slice i begins (i = 0: the camera's near plane; i = kShadowCascades:
// kShadowFarM).
double ShadowSplitM(const Camera& camera, int i);

// The cascades for the input's view: each held one where its slice still fits inside its window
// and its casters' rectangle (its drift updated), a new window around the slice elsewhere. A held
// window is kept only for the input's sun, unless keep_held_sun allows it to keep the sun it was
// drawn for (a moving sun's tiles catch up one a frame: frame_cache_policy.h); a new window is
// always fitted for the input's sun.
ShadowCascades FitShadowCascades(const CascadeFitInput& input, const HeldCascades& held = {},
                                 const std::array<bool, kShadowCascades>& keep_held_sun = {});

}  // namespace aerial
