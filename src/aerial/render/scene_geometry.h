#pragma once
// The scene's meshes on the GPU: opaque meshes in one vertex and index buffer; transparent meshes
// in another, whose triangles are re-sorted back to front for every camera (they are blended).
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "aerial/scene/scene.h"
#include "aerial/vk/resources.h"

namespace aerial {

class SceneGeometry {
 public:
  SceneGeometry(const vk::Context& context, const Scene& scene);

  // Rewrites the transparent index buffer, farthest triangle first, for a camera position.
  void SortTransparent(const glm::dvec3& camera_position);

  const vk::Buffer& opaque_vertices() const { return opaque_vertices_; }
  const vk::Buffer& opaque_indices() const { return opaque_indices_; }
  uint32_t opaque_index_count() const { return opaque_index_count_; }
  const vk::Buffer& transparent_vertices() const { return transparent_vertices_; }
  const vk::Buffer& transparent_indices() const { return transparent_indices_; }
  uint32_t transparent_index_count() const { return uint32_t(transparent_triangles_.size() * 3); }

 private:
  struct Triangle {
    std::array<uint32_t, 3> indices;
    glm::dvec3 centroid;
  };
  struct Packed {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
  };
  static Packed Pack(const Scene& scene, bool transparent);
  SceneGeometry(const vk::Context& context, const Packed& opaque, const Packed& transparent);

  uint32_t opaque_index_count_ = 0;
  std::vector<Triangle> transparent_triangles_;
  vk::Buffer opaque_vertices_, opaque_indices_, transparent_vertices_, transparent_indices_;
};

}  // namespace aerial
