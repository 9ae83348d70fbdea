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

SceneGeometry::Packed SceneGeometry::Pack(const Scene& scene, bool transparent) {
  Packed packed;
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.transparent != transparent) continue;
    uint32_t base = uint32_t(packed.vertices.size());
    packed.vertices.insert(packed.vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    for (uint32_t index : mesh.indices) packed.indices.push_back(base + index);
  }
  return packed;
}

SceneGeometry::SceneGeometry(const vk::Context& context, const Scene& scene)
    : SceneGeometry(context, Pack(scene, false), Pack(scene, true)) {}

SceneGeometry::SceneGeometry(const vk::Context& context, const Packed& opaque,
                             const Packed& transparent)
    : opaque_index_count_(uint32_t(opaque.indices.size())),
      opaque_vertices_(Upload(context, std::as_bytes(std::span(opaque.vertices)),
                              ::vk::BufferUsageFlagBits::eVertexBuffer)),
      opaque_indices_(Upload(context, std::as_bytes(std::span(opaque.indices)),
                             ::vk::BufferUsageFlagBits::eIndexBuffer)),
      transparent_vertices_(Upload(context, std::as_bytes(std::span(transparent.vertices)),
                                   ::vk::BufferUsageFlagBits::eVertexBuffer)),
      transparent_indices_(Upload(context, std::as_bytes(std::span(transparent.indices)),
                                  ::vk::BufferUsageFlagBits::eIndexBuffer)) {
  for (size_t i = 0; i + 2 < transparent.indices.size(); i += 3) {
    Triangle triangle{{transparent.indices[i], transparent.indices[i + 1], transparent.indices[i + 2]},
                      glm::dvec3(0.0)};
    for (uint32_t index : triangle.indices)
      triangle.centroid += glm::dvec3(transparent.vertices[index].position) / 3.0;
    transparent_triangles_.push_back(triangle);
  }
}

void SceneGeometry::SortTransparent(const glm::dvec3& camera_position) {
  if (transparent_triangles_.empty()) return;
  std::sort(transparent_triangles_.begin(), transparent_triangles_.end(),
            [&](const Triangle& a, const Triangle& b) {
              return glm::distance(a.centroid, camera_position) > glm::distance(b.centroid, camera_position);
            });
  std::vector<uint32_t> indices;
  indices.reserve(transparent_triangles_.size() * 3);
  for (const Triangle& t : transparent_triangles_) indices.insert(indices.end(), t.indices.begin(), t.indices.end());
  transparent_indices_.Write(std::as_bytes(std::span(indices)));
}

}  // namespace aerial
