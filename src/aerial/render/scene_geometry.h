#pragma once
// The scene's meshes on the GPU: opaque meshes in one vertex and index buffer, each drawn on its
// own (MeshDraw); transparent meshes in another, whose triangles are
// re-sorted back to front for every camera (they are blended). The sorted indices have one
// buffer per frame in flight, so sorting for a frame never rewrites what an earlier one reads.
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "aerial/scene.h"
#include "aerial/vk/resources.h"

namespace aerial {

// One opaque mesh's triangles in the shared buffers, and what decides how it is drawn: its faces'
// culling, and how large its triangles may be on screen (surface_reads.h).
struct MeshDraw {
  uint32_t first_index = 0, index_count = 0;
  bool double_sided = false;  // drawn without back-face culling
  glm::dvec3 center{0.0};     // a sphere around every vertex
  double radius_m = 0.0;
  double longest_edge_m = 0.0;  // of its triangles
  double largest_rise_m = 0.0;  // the largest height difference along any of its triangles' edges
  bool ground = false;          // the ground's own mesh (its albedo detail: shaders/include/ground_detail.glsl)
};

class SceneGeometry {
 public:
  // extra_opaque: the ground's meshes, drawn with the scene's opaque ones (the reference terrain
  // mesh; MeshDraw::ground).
  SceneGeometry(const vk::Context& context, const Scene& scene, uint32_t frames_in_flight,
                const std::vector<Mesh>& extra_opaque = {});

  // Rewrites slot's transparent index buffer, farthest triangle first, for a camera position.
  void SortTransparent(const glm::dvec3& camera_position, uint32_t slot);

  const vk::Buffer& opaque_vertices() const { return opaque_vertices_; }
  const vk::Buffer& opaque_indices() const { return opaque_indices_; }
  const std::vector<MeshDraw>& opaque_draws() const { return opaque_draws_; }
  uint32_t opaque_index_count() const { return opaque_index_count_; }
  const vk::Buffer& transparent_vertices() const { return transparent_vertices_; }
  const vk::Buffer& transparent_indices(uint32_t slot) const { return transparent_indices_[slot]; }
  uint32_t transparent_index_count() const { return uint32_t(transparent_triangles_.size() * 3); }

 private:
  struct Triangle {
    std::array<uint32_t, 3> indices;
    glm::dvec3 centroid;
    double distance_squared;  // from the camera of the last sort
  };
  struct Packed {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    void Append(const Mesh& mesh);
  };
  struct Packing {
    Packed opaque, transparent;
    std::vector<MeshDraw> opaque_draws;
  };
  static Packing Pack(const Scene& scene, const std::vector<Mesh>& extra_opaque);
  SceneGeometry(const vk::Context& context, const Packing& packing, uint32_t frames_in_flight);

  std::vector<MeshDraw> opaque_draws_;
  uint32_t opaque_index_count_ = 0;
  std::vector<Triangle> transparent_triangles_;
  std::vector<uint32_t> sorted_;  // scratch, kept so that sorting does not allocate
  vk::Buffer opaque_vertices_, opaque_indices_, transparent_vertices_;
  std::vector<vk::Buffer> transparent_indices_;
};

}  // namespace aerial
