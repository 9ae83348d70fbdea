#include "aerial/scene/mesh_ray_cast.h"

#include <gtest/gtest.h>

#include "aerial/scene/primitives.h"

namespace aerial {
namespace {

constexpr glm::vec3 kGrey{0.45f, 0.45f, 0.45f};

// A 10 m cube standing on the origin, faces along x, y and z.
Mesh Cube(bool double_sided = false, bool transparent = false) {
  Mesh mesh;
  mesh.double_sided = double_sided;
  mesh.transparent = transparent;
  AppendBox(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {10, 10, 10}, {kGrey, 1.0f});
  return mesh;
}

TEST(MeshRayCast, HitsTheNearFaceWithItsNormalAndAlbedo) {
  // From 100 m south, toward a point of the south face 3 m up and 2 m east of its center.
  glm::dvec3 origin(2, -100, 3);
  auto hit = CastRay({Cube()}, origin, {0, 1, 0});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance_m, 95.0, 1e-9);
  EXPECT_NEAR(glm::distance(hit->normal, glm::dvec3(0, -1, 0)), 0.0, 1e-7);
  EXPECT_NEAR(hit->albedo.r, 0.45, 1e-7);
  // Along the diagonal of the top face, from above.
  hit = CastRay({Cube()}, {1, 1, 50}, {0, 0, -1});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance_m, 40.0, 1e-9);
  EXPECT_NEAR(hit->normal.z, 1.0, 1e-7);
}

TEST(MeshRayCast, MissesBesideTheMesh) {
  EXPECT_FALSE(CastRay({Cube()}, {5.01, -100, 3}, {0, 1, 0}));
  EXPECT_FALSE(CastRay({Cube()}, {0, -100, 3}, {0, -1, 0})) << "behind the origin";
}

// Seen from inside, a single-sided box shows only back faces: culled, as the renderer culls them.
// A double-sided one shows its far face, lit on the side seen.
TEST(MeshRayCast, BackFacesCulledUnlessDoubleSided) {
  EXPECT_FALSE(CastRay({Cube()}, {0, 0, 5}, {0, 1, 0}));
  auto hit = CastRay({Cube(true)}, {0, 0, 5}, {0, 1, 0});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance_m, 5.0, 1e-9);
  EXPECT_NEAR(hit->normal.y, -1.0, 1e-7) << "the +forward face's normal, turned toward the ray's origin";
}

TEST(MeshRayCast, NearestOpaqueMeshOnly) {
  Mesh far = Cube();
  for (Vertex& v : far.vertices) v.position.y += 50.0f;
  EXPECT_NEAR(CastRay({far, Cube()}, {0, -100, 5}, {0, 1, 0})->distance_m, 95.0, 1e-9);
  EXPECT_NEAR(CastRay({far, Cube(false, true)}, {0, -100, 5}, {0, 1, 0})->distance_m, 145.0, 1e-9)
      << "the transparent cube is not hit";
}

// Smooth shading: the vertex normals and albedos are interpolated at the hit.
TEST(MeshRayCast, InterpolatesVertexNormalsAndAlbedos) {
  Mesh mesh;
  mesh.vertices = {{{0, 0, 0}, {0, 0, 1}, {0, 0, 0}, 1.0f},
                   {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}, 1.0f},
                   {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, 1.0f}};
  mesh.indices = {0, 1, 2};
  auto hit = CastRay({mesh}, {0.25, 0.5, 1.0}, {0, 0, -1});  // barycentric (0.25, 0.25, 0.5)
  ASSERT_TRUE(hit);
  EXPECT_NEAR(glm::distance(hit->normal, glm::normalize(glm::dvec3(0.25, 0.5, 0.25))), 0.0, 1e-12);
  EXPECT_NEAR(glm::distance(hit->albedo, glm::dvec3(0.25, 0.5, 0.0)), 0.0, 1e-12);
}

}  // namespace
}  // namespace aerial
