#include "aerial/scene/terrain.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
// between the lush and the dry one, times the ground's detail, 1 +- 0.45): never blue.
TEST(TerrainSurface, FlatValleyFloorAtTheOriginIsGrassFacingUp) {
  TerrainSurface s = TerrainSurfaceAt(0.0, 0.0, kR);
  EXPECT_NEAR(s.normal.z, 1.0, 1e-6);
  EXPECT_GT(s.albedo.g, 0.55 * 0.09);
  EXPECT_LT(s.albedo.g, 1.45 * 0.20);
  EXPECT_LT(s.albedo.b, s.albedo.g);
}

// The terrain's vertex at p on a grid of the given step (its neighbours a step away in x and y).
Vertex VertexOnGrid(double x, double y, double step) {
  return TerrainVertex(TerrainPoint(x, y, kR), TerrainPoint(x + step, y, kR) - TerrainPoint(x - step, y, kR),
                       TerrainPoint(x, y + step, kR) - TerrainPoint(x, y - step, kR), kR);
}

// The ground's detail is band-limited to the grid that samples it: on the flat valley floor (within
// 250 m of the origin: no hills, the same material on any grid), a 2 m grid has every octave of it
// (wavelengths 10-160 m) and a 400 m grid none (a wavelength needs at least two steps). So their
// albedos differ by one factor in all three channels, within the detail's +-45%, and it varies from
// point to point; without the band limit the coarse grid would alias the detail and the factor
// would be 1 everywhere.
TEST(TerrainSurface, DetailFollowsTheGridStep) {
  double low = HUGE_VAL, high = -HUGE_VAL;
  for (int i = 0; i < 200; ++i) {
    double angle = 0.7 * i, radius = 1.2 * i;
    double x = radius * std::cos(angle), y = radius * std::sin(angle);
    glm::vec3 fine = VertexOnGrid(x, y, 2.0).albedo, coarse = VertexOnGrid(x, y, 400.0).albedo;
    double factor = fine.g / coarse.g;
    EXPECT_NEAR(fine.r / coarse.r, factor, 1e-5) << x << " " << y;
    EXPECT_NEAR(fine.b / coarse.b, factor, 1e-5) << x << " " << y;
    low = std::min(low, factor);
    high = std::max(high, factor);
  }
  std::printf("fine / coarse grid albedo: %.3f to %.3f\n", low, high);
  EXPECT_GE(low, 0.55 - 1e-6);
  EXPECT_LE(high, 1.45 + 1e-6);
  EXPECT_GT(high - low, 0.2) << "the detail shows on the fine grid";
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

}  // namespace
}  // namespace aerial
