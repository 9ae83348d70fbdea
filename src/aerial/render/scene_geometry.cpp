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

}  // namespace

void SceneGeometry::Packed::Append(const Mesh& mesh) {
  uint32_t base = uint32_t(vertices.size());
  vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
  for (uint32_t index : mesh.indices) indices.push_back(base + index);
}

SceneGeometry::Packing SceneGeometry::Pack(const Scene& scene, const std::vector<Mesh>& extra_opaque) {
  Packing packing;
  std::vector<const Mesh*> single_sided, double_sided;
  for (const std::vector<Mesh>* meshes : {&scene.meshes, &extra_opaque}) {
    for (const Mesh& mesh : *meshes) {
      if (mesh.transparent) {
        packing.transparent.Append(mesh);
      } else {
        (mesh.double_sided ? double_sided : single_sided).push_back(&mesh);
      }
    }
  }
  for (const Mesh* mesh : single_sided) packing.opaque.Append(*mesh);
  packing.single_sided_index_count = uint32_t(packing.opaque.indices.size());
  for (const Mesh* mesh : double_sided) packing.opaque.Append(*mesh);
  return packing;
}

SceneGeometry::SceneGeometry(const vk::Context& context, const Scene& scene, uint32_t frames_in_flight,
                             const std::vector<Mesh>& extra_opaque)
    : SceneGeometry(context, Pack(scene, extra_opaque), frames_in_flight) {}

SceneGeometry::SceneGeometry(const vk::Context& context, const Packing& packing,
                             uint32_t frames_in_flight)
    : single_sided_index_count_(packing.single_sided_index_count),
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
