#include "aerial/render/scene_geometry.h"

#include <algorithm>

namespace aerial {
namespace {

vk::Buffer Upload(const vk::Context& context, std::span<const std::byte> bytes,
                  ::vk::BufferUsageFlags usage) {
  // Host-visible: written once (opaque) or every frame (sorted transparent indices). A discrete
  // GPU would prefer a staging copy for the static meshes; lavapipe has one kind of memory.
  vk::Buffer buffer(context, {.size = std::max<size_t>(bytes.size(), 16), .usage = usage,
                              .host_visible = true});
  if (!bytes.empty()) buffer.Write(bytes);
  return buffer;
}

// The mesh's bounding sphere (around the centre of its vertices' box) and its longest edge.
MeshDraw MeshBounds(const Mesh& mesh) {
  MeshDraw draw{.double_sided = mesh.double_sided};
  if (mesh.vertices.empty()) return draw;
  glm::dvec3 low(mesh.vertices[0].position), high = low;
  for (const Vertex& v : mesh.vertices) {
    low = glm::min(low, glm::dvec3(v.position));
    high = glm::max(high, glm::dvec3(v.position));
  }
  draw.center = 0.5 * (low + high);
  for (const Vertex& v : mesh.vertices)
    draw.radius_m = std::max(draw.radius_m, glm::length(glm::dvec3(v.position) - draw.center));
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
    for (int k = 0; k < 3; ++k) {
      glm::dvec3 a(mesh.vertices[mesh.indices[i + k]].position), b(mesh.vertices[mesh.indices[i + (k + 1) % 3]].position);
      draw.longest_edge_m = std::max(draw.longest_edge_m, glm::length(b - a));
      draw.largest_rise_m = std::max(draw.largest_rise_m, std::abs(b.z - a.z));
    }
  return draw;
}

}  // namespace

void SceneGeometry::Packed::Append(const Mesh& mesh) {
  uint32_t base = uint32_t(vertices.size());
  vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
  for (uint32_t index : mesh.indices) indices.push_back(base + index);
}

SceneGeometry::Packing SceneGeometry::Pack(const Scene& scene, const std::vector<Mesh>& extra_opaque) {
  Packing packing;
  for (const std::vector<Mesh>* meshes : {&scene.meshes, &extra_opaque}) {
    for (const Mesh& mesh : *meshes) {
      if (mesh.transparent) {
        packing.transparent.Append(mesh);
        continue;
      }
      MeshDraw draw = MeshBounds(mesh);
      draw.first_index = uint32_t(packing.opaque.indices.size());
      draw.index_count = uint32_t(mesh.indices.size());
      draw.ground = meshes == &extra_opaque;
      packing.opaque.Append(mesh);
      if (draw.index_count > 0) packing.opaque_draws.push_back(draw);
    }
  }
  return packing;
}

SceneGeometry::SceneGeometry(const vk::Context& context, const Scene& scene, uint32_t frames_in_flight,
                             const std::vector<Mesh>& extra_opaque)
    : SceneGeometry(context, Pack(scene, extra_opaque), frames_in_flight) {}

SceneGeometry::SceneGeometry(const vk::Context& context, const Packing& packing,
                             uint32_t frames_in_flight)
    : opaque_draws_(packing.opaque_draws),
      opaque_index_count_(uint32_t(packing.opaque.indices.size())),
      opaque_vertices_(Upload(context, std::as_bytes(std::span(packing.opaque.vertices)),
                              ::vk::BufferUsageFlagBits::eVertexBuffer)),
      opaque_indices_(Upload(context, std::as_bytes(std::span(packing.opaque.indices)),
                             ::vk::BufferUsageFlagBits::eIndexBuffer)),
      transparent_vertices_(Upload(context, std::as_bytes(std::span(packing.transparent.vertices)),
                                   ::vk::BufferUsageFlagBits::eVertexBuffer)) {
  const Packed& transparent = packing.transparent;
  for (uint32_t slot = 0; slot < frames_in_flight; ++slot) {
    transparent_indices_.push_back(Upload(context, std::as_bytes(std::span(transparent.indices)),
                                          ::vk::BufferUsageFlagBits::eIndexBuffer));
  }
  for (size_t i = 0; i + 2 < transparent.indices.size(); i += 3) {
    Triangle triangle{{transparent.indices[i], transparent.indices[i + 1], transparent.indices[i + 2]},
                      glm::dvec3(0.0), 0.0};
    for (uint32_t index : triangle.indices)
      triangle.centroid += glm::dvec3(transparent.vertices[index].position) / 3.0;
    transparent_triangles_.push_back(triangle);
  }
  sorted_.reserve(transparent.indices.size());
}

void SceneGeometry::SortTransparent(const glm::dvec3& camera_position, uint32_t slot) {
  if (transparent_triangles_.empty()) return;
  // Squared distances, computed once per triangle: the order is the same.
  for (Triangle& t : transparent_triangles_) {
    glm::dvec3 d = t.centroid - camera_position;
    t.distance_squared = glm::dot(d, d);
  }
  std::sort(transparent_triangles_.begin(), transparent_triangles_.end(),
            [](const Triangle& a, const Triangle& b) { return a.distance_squared > b.distance_squared; });
  sorted_.clear();
  for (const Triangle& t : transparent_triangles_) sorted_.insert(sorted_.end(), t.indices.begin(), t.indices.end());
  transparent_indices_[slot].Write(std::as_bytes(std::span(sorted_)));
}

}  // namespace aerial
