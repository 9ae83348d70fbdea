#include "aerial/terrain/scene_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "aerial/scene/mesh_ray_cast.h"
#include "aerial/scene/terrain.h"

namespace aerial {
namespace {

constexpr double kR = 6360e3;

const Scene& NoonScene() {
  static const Scene scene = BuildDefaultScene(kR);  // the "noon" view: 30 m above the valley
  return scene;
}

// At 180 rows the terrain's selection takes 720 (lod_selection.h): K = 720 / (2 tan 25 deg).
TEST(SceneSurface, TerrainToleranceIsTheLodBoundWithItsMargin) {
  double k = 720.0 / (2.0 * std::tan(25.0 * std::numbers::pi / 180.0));
  EXPECT_NEAR(TerrainTolerancePerM(NoonScene().camera, 180, 4.0), 1.25 * 4.0 / k, 1e-12);
}

// The ray toward the 1 km landmark's centre meets its camera-facing side: the scene's normal
// (toward the camera) and albedo at the ray cast's depth, none 1% further, behind it.
TEST(SceneSurface, MeshAtTheRenderersDepth) {
  const Scene& scene = NoonScene();
  const Mesh* landmark = nullptr;
  for (const Mesh& mesh : scene.meshes)
    if (mesh.name == "landmark_1km") landmark = &mesh;
  ASSERT_NE(landmark, nullptr);
  glm::dvec3 centre(0.0);
  for (const Vertex& v : landmark->vertices) centre += glm::dvec3(v.position) / double(landmark->vertices.size());
  glm::dvec3 ray = glm::normalize(centre - scene.camera.position);
  double depth = CastRay(scene.meshes, scene.camera.position, ray)->distance_m;
  auto surface = SurfaceAtDepth(scene, kR, ray, depth, 0.01);
  ASSERT_TRUE(surface);
  EXPECT_LT(glm::dot(surface->normal, ray), -0.9);
  EXPECT_NEAR(surface->albedo[0], 0.42, 1e-6);  // the landmarks' stone (default_scene.cpp)
  EXPECT_NEAR(glm::length(surface->point - glm::dvec3(0, 0, kR) - (scene.camera.position + depth * ray)), 0.0, 1e-6);
  EXPECT_FALSE(SurfaceAtDepth(scene, kR, ray, 1.01 * depth, 0.01));
}

// 5 degrees down, north, the ray meets the valley floor ~340 m out. A depth within the tolerance
// of the crossing is terrain, lit on the height function's surface; 100 m short of it, 9 m up in
// the air, none.
TEST(SceneSurface, TerrainWithinTheTolerance) {
  const Scene& scene = NoonScene();
  const double down = 5.0 * std::numbers::pi / 180.0, tolerance = TerrainTolerancePerM(scene.camera, 180, 4.0);
  glm::dvec3 ray(0.0, std::cos(down), -std::sin(down));
  auto above = [&](double t) { return HeightAboveTerrainM(scene.camera.position + t * ray, kR); };
  double near = 0.0, far = 1000.0;
  for (int i = 0; i < 60; ++i) (above((near + far) / 2) > 0.0 ? near : far) = (near + far) / 2;
  ASSERT_NEAR(near, 340.0, 60.0);
  for (double depth : {near, near + 3.0, near - 3.0}) {
    auto surface = SurfaceAtDepth(scene, kR, ray, depth, tolerance);
    ASSERT_TRUE(surface) << depth;
    glm::dvec3 sea_level = SeaLevelPoint(scene.camera.position + depth * ray, kR);
    TerrainSurface expected = TerrainSurfaceAt(sea_level.x, sea_level.y, kR);
    EXPECT_NEAR(glm::length(surface->point - glm::dvec3(0, 0, kR) - expected.point), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(surface->normal - expected.normal), 0.0, 1e-12);
    EXPECT_NEAR(surface->albedo[1], expected.albedo.g, 1e-12);
  }
  EXPECT_FALSE(SurfaceAtDepth(scene, kR, ray, near - 100.0, tolerance));
}

}  // namespace
}  // namespace aerial
