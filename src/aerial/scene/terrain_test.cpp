#include "aerial/scene/terrain.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace aerial {
namespace {

constexpr double kR = 6360e3;

// Points in the valley, on the corridor's walls and among the mountains (5-80 km).
constexpr double kPoints[][2] = {{150.0, 40.0}, {-900.0, 2500.0}, {3000.0, 20e3}, {-12e3, 31e3},
                                 {25e3, -8e3},  {-40e3, -47e3},   {61e3, 52e3}};

// The normal is the surface's in every direction, not only along x and y where it was taken: the
// chord across p over 2 cm in any of 8 directions is perpendicular to it, within the central
// differences' error bound (~5e-6, terrain.h).
TEST(TerrainSurface, NormalIsPerpendicularToTheSurfaceInEveryDirection) {
  for (const auto& [x, y] : kPoints) {
    TerrainSurface s = TerrainSurfaceAt(x, y, kR);
    EXPECT_NEAR(glm::length(s.normal), 1.0, 1e-12);
    EXPECT_GT(glm::dot(s.normal, glm::normalize(s.point - glm::dvec3(0.0, 0.0, -kR))), 0.0) << "faces up";
    for (int k = 0; k < 8; ++k) {
      double angle = k * std::numbers::pi / 8.0, delta = 0.01;
      double dx = delta * std::cos(angle), dy = delta * std::sin(angle);
      glm::dvec3 chord = TerrainPoint(x + dx, y + dy, kR) - TerrainPoint(x - dx, y - dy, kR);
      EXPECT_NEAR(glm::dot(glm::normalize(chord), s.normal), 0.0, 1e-5) << x << " " << y << " " << k;
    }
  }
}

// Where the surface is flat, the normal is the local vertical and the albedo a grass (terrain.cpp:
// between the lush and the dry one): never blue.
TEST(TerrainSurface, FlatValleyFloorAtTheOriginIsGrassFacingUp) {
  TerrainSurface s = TerrainSurfaceAt(0.0, 0.0, kR);
  EXPECT_NEAR(s.normal.z, 1.0, 1e-6);
  EXPECT_GE(s.albedo.g, 0.09 - 1e-9);
  EXPECT_LE(s.albedo.g, 0.20 + 1e-9);
  EXPECT_LT(s.albedo.b, s.albedo.g);
}

TEST(TerrainSurface, SeaLevelPointInvertsSurfacePoint) {
  for (const auto& [x, y] : kPoints) {
    glm::dvec3 p = SurfacePoint(x, y, 1234.0, kR);
    glm::dvec3 sea_level = SeaLevelPoint(p, kR);
    EXPECT_NEAR(sea_level.x, x, 1e-6);
    EXPECT_NEAR(sea_level.y, y, 1e-6);
    EXPECT_NEAR(HeightAboveTerrainM(p, kR), 1234.0 - TerrainHeightM(x, y), 1e-6);
    EXPECT_NEAR(HeightAboveTerrainM(TerrainPoint(x, y, kR), kR), 0.0, 1e-6);
  }
}

// kTerrainMaxHeightM bounds every height (the shadows in the air skip the shadow map above it)
// and is not loose: the highest of the heights sampled every 200 m (3137 m) lies within 200 m
// below it.
TEST(TerrainHeight, MaxHeightBoundsThePeaksClosely) {
  double highest = 0.0;
  for (double x = -kTerrainRadiusM; x <= kTerrainRadiusM; x += 200.0)
    for (double y = -kTerrainRadiusM; y <= kTerrainRadiusM; y += 200.0)
      if (x * x + y * y <= kTerrainRadiusM * kTerrainRadiusM) highest = std::max(highest, TerrainHeightM(x, y));
  EXPECT_LE(highest, kTerrainMaxHeightM);
  EXPECT_GT(highest, kTerrainMaxHeightM - 200.0);
}

// kTerrainMinHeightM bounds every height from below (how far a shadow may reach along a sun ray
// starts there: frame_cache_policy.h), and the valley's hills do dip below the sphere (-2.0 m
// lowest, sampled every 50 m over the valley's hills, 3 km around the camera).
TEST(TerrainHeight, MinHeightBoundsTheValleyHills) {
  double lowest = 0.0;
  for (double x = -kTerrainRadiusM; x <= kTerrainRadiusM; x += 200.0)
    for (double y = -kTerrainRadiusM; y <= kTerrainRadiusM; y += 200.0)
      if (x * x + y * y <= kTerrainRadiusM * kTerrainRadiusM) lowest = std::min(lowest, TerrainHeightM(x, y));
  for (double x = -3000.0; x <= 3000.0; x += 50.0)
    for (double y = -3000.0; y <= 3000.0; y += 50.0) lowest = std::min(lowest, TerrainHeightM(x, y));
  EXPECT_GE(lowest, kTerrainMinHeightM);
  EXPECT_LT(lowest, -1.0);
}

}  // namespace
}  // namespace aerial
