#include "aerial/scene/gltf_loader.h"

#include <algorithm>
#include <cctype>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <string_view>
#include <utility>
#include <vector>

#include "aerial/core/input_limits.h"
#include "aerial/core/json_depth.h"
#include "aerial/error.h"
#include "aerial/scene/glb_layout.h"
#include "aerial/scene/gltf_accessors.h"
#include "aerial/scene/gltf_file_system.h"
#include "aerial/scene/gltf_parse_memory.h"
#include "aerial/scene/scene_limits.h"
#include "aerial/scene/tiny_gltf_config.h"

namespace aerial {
namespace {

// glTF y-up to the world's z-up: (x, y, z) -> (x, -z, y), a +90 degree turn about x.
const glm::dmat4 kYUpToZUp(1, 0, 0, 0,   // image of x (columns)
                           0, 0, 1, 0,   // image of y
                           0, -1, 0, 0,  // image of z
                           0, 0, 0, 1);

std::string ModeName(int mode) {
  static const char* kNames[] = {"POINTS",    "LINES",          "LINE_LOOP",   "LINE_STRIP",
                                 "TRIANGLES", "TRIANGLE_STRIP", "TRIANGLE_FAN"};
  std::string name = mode >= 0 && mode < 7 ? kNames[mode] : "unknown";
  return name + " (" + std::to_string(mode) + ")";
}

glm::dmat4 LocalTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major both
  glm::dmat4 transform(1.0);
  if (node.translation.size() == 3)
    transform[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  if (node.rotation.size() == 4) {
    // glTF stores quaternions as (x, y, z, w); glm's constructor takes w first.
    glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    transform *= glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3)
    transform = glm::scale(transform, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return transform;
}

struct Material {
  glm::vec3 albedo{1.0f};
  float opacity = 1.0f;
  bool blend = false;
  bool double_sided = false;  // glTF's default: back faces are culled
};

Material MaterialOf(const tinygltf::Model& model, int index) {
  Material material;
  if (index < 0 || static_cast<size_t>(index) >= model.materials.size()) return material;
  const tinygltf::Material& m = model.materials[index];
  const std::vector<double>& color = m.pbrMetallicRoughness.baseColorFactor;
  if (color.size() == 4) {
    for (int i = 0; i < 3; ++i)
      material.albedo[i] = static_cast<float>(std::clamp(color[i], 0.0, 1.0));
    material.opacity = static_cast<float>(std::clamp(color[3], 0.0, 1.0));
  }
  material.blend = m.alphaMode == "BLEND";
  material.double_sided = m.doubleSided;
  if (!material.blend) material.opacity = 1.0f;
  return material;
}

glm::vec3 SafeNormalize(const glm::dvec3& v) {
  double length = glm::length(v);
  return length > 0.0 ? glm::vec3(v / length) : glm::vec3(0.0f, 0.0f, 1.0f);
}

// Appends one primitive, transformed by to_world (node transforms and the axis change).
void AppendPrimitive(const GltfReader& reader, const tinygltf::Primitive& primitive,
                     const Material& material, const glm::dmat4& to_world, const std::string& field,
                     Mesh& mesh) {
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES)
    reader.Fail(field + ".mode", ModeName(primitive.mode), "TRIANGLES (4)");
  auto position = primitive.attributes.find("POSITION");
  if (position == primitive.attributes.end())
    reader.Fail(field + ".attributes", "no POSITION", "a POSITION attribute");
  std::vector<glm::dvec3> positions = reader.ReadVec3(position->second, field + ".POSITION");
  std::vector<uint32_t> indices;
  if (primitive.indices >= 0) {
    indices = reader.ReadIndices(primitive.indices, field + ".indices");
  } else {
    indices.resize(positions.size());
    for (size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<uint32_t>(i);
  }
  if (indices.size() % 3 != 0)
    reader.Fail(field + ".indices", std::to_string(indices.size()) + " indices", "a multiple of 3");
  // Values read from a buffer are not shown: only the written counts and positions in it.
  for (size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] >= positions.size())
      reader.Fail(field + ".indices", "element " + std::to_string(i),
                  "an index below the vertex count " + std::to_string(positions.size()));
  }

  for (size_t i = 0; i < positions.size(); ++i) {
    positions[i] = glm::dvec3(to_world * glm::dvec4(positions[i], 1.0));
    // Checked in double, before the positions become floats (a cast out of float's range is
    // undefined) and before the scene's distance check, which a NaN would pass.
    if (!(glm::length(positions[i]) <= kMaxModelCoordinateM))
      reader.Fail(field + ".POSITION", "vertex " + std::to_string(i) + " after the node transforms",
                  "finite coordinates within " + FormatNumber(kMaxModelCoordinateM) +
                      " m of the model's origin (coordinates read from buffers are not shown)");
  }
  // A mirroring transform turns counter-clockwise triangles clockwise (glTF 2.0 spec, 3.7.4).
  glm::dmat3 linear(to_world);
  bool mirrored = glm::determinant(linear) < 0.0;
  if (mirrored)
    for (size_t i = 0; i < indices.size(); i += 3) std::swap(indices[i + 1], indices[i + 2]);

  auto normal = primitive.attributes.find("NORMAL");
  if (normal != primitive.attributes.end()) {
    std::vector<glm::dvec3> normals = reader.ReadVec3(normal->second, field + ".NORMAL");
    if (normals.size() != positions.size())
      reader.Fail(field + ".NORMAL", std::to_string(normals.size()) + " normals",
                  std::to_string(positions.size()) + ", one per POSITION");
    // Normals transform by the inverse transpose, which keeps them perpendicular to surfaces
    // under non-uniform scale.
    glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
    uint32_t first = static_cast<uint32_t>(mesh.vertices.size());
    for (size_t i = 0; i < positions.size(); ++i) {
      mesh.vertices.push_back({glm::vec3(positions[i]), SafeNormalize(normal_matrix * normals[i]),
                               material.albedo, material.opacity});
    }
    for (uint32_t index : indices) mesh.indices.push_back(first + index);
    return;
  }
  // No normals: each triangle gets its own vertices carrying its face normal.
  for (size_t i = 0; i < indices.size(); i += 3) {
    const glm::dvec3 &a = positions[indices[i]], &b = positions[indices[i + 1]],
                     &c = positions[indices[i + 2]];
    glm::vec3 face = SafeNormalize(glm::cross(b - a, c - a));
    for (const glm::dvec3* p : {&a, &b, &c}) {
      mesh.indices.push_back(static_cast<uint32_t>(mesh.vertices.size()));
      mesh.vertices.push_back({glm::vec3(*p), face, material.albedo, material.opacity});
    }
  }
}

void AppendMesh(const GltfReader& reader, const tinygltf::Model& model, int mesh_index,
                const glm::dmat4& to_world, Mesh& mesh) {
  std::string field = "meshes[" + std::to_string(mesh_index) + "]";
  if (mesh_index < 0 || static_cast<size_t>(mesh_index) >= model.meshes.size())
    reader.Fail("node mesh", std::to_string(mesh_index), "an existing mesh index");
  const std::vector<tinygltf::Primitive>& primitives = model.meshes[mesh_index].primitives;
  for (size_t i = 0; i < primitives.size(); ++i) {
    Material material = MaterialOf(model, primitives[i].material);
    mesh.transparent = mesh.transparent || material.blend;
    mesh.double_sided = mesh.double_sided || material.double_sided;
    AppendPrimitive(reader, primitives[i], material, to_world,
                    field + ".primitives[" + std::to_string(i) + "]", mesh);
  }
}

tinygltf::Model ReadModel(const std::filesystem::path& path, MemoryTally& tally) {
  tinygltf::Model model;
  std::string base_dir = path.parent_path().string();
  GltfFileSystem files(model, base_dir, kMaxGltfBytes);
  std::vector<unsigned char> bytes = files.ReadModelFile(path);
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  bool binary = extension == ".glb";
  std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  std::string_view json = binary ? CheckedGlbJson(bytes, path.string()) : text;
  CheckJsonDepth(json, path.string());
  tally.Add(GltfParseBytes(json, bytes.size()));

  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(files.Callbacks());
  // Textures are not used: accept images without decoding them (no stb_image in this build).
  loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int,
                           const unsigned char*, int, void*) { return true; },
                        nullptr);
  std::string error, warning;
  // kMaxGltfBytes keeps the size inside tinygltf's unsigned int.
  auto size = static_cast<unsigned int>(bytes.size());
  bool ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), size,
                                                 base_dir)
                   : loader.LoadASCIIFromString(&model, &error, &warning, text.data(), size,
                                                base_dir);
  files.RethrowFailure();
  if (!ok) {
    files.RethrowRefusedBuffer();
    while (!error.empty() && error.back() == '\n') error.pop_back();
    throw Error("glTF file", path.string(), "valid glTF 2.0 (" + Shortened(error) + ")");
  }
  return model;
}

}  // namespace

uint64_t HeldMeshBytes(const Mesh& mesh) {
  return 3 * (uint64_t(mesh.vertices.capacity()) * sizeof(Vertex) + uint64_t(mesh.indices.capacity()) * sizeof(uint32_t));
}

Mesh LoadGltfMesh(const std::filesystem::path& path, const std::string& name, const MemoryBudget& budget) {
  MemoryTally tally(budget, "glTF model", path.string(), "JSON parse and geometry");
  tinygltf::Model model = ReadModel(path, tally);
  GltfReader reader(model, path.string(), tally);
  Mesh mesh;
  mesh.name = name;

  if (model.scenes.empty()) {
    // A file without scenes holds a library of meshes: take each once, untransformed.
    for (size_t i = 0; i < model.meshes.size(); ++i)
      AppendMesh(reader, model, static_cast<int>(i), kYUpToZUp, mesh);
  } else {
    size_t scene = model.defaultScene >= 0 ? static_cast<size_t>(model.defaultScene) : 0;
    if (scene >= model.scenes.size())
      reader.Fail("scene", std::to_string(scene), "an existing scene index");
    // Depth-first over the node hierarchy. A valid glTF is a forest (glTF 2.0 spec, 3.5.3):
    // a node reached twice (listed twice, by two parents or in a cycle) is refused, so the
    // walk visits each node once, however the file is shaped.
    struct Pending {
      int node;
      glm::dmat4 parent;
    };
    std::vector<Pending> pending;
    std::vector<bool> visited(model.nodes.size(), false);
    for (int root : model.scenes[scene].nodes) pending.push_back({root, kYUpToZUp});
    while (!pending.empty()) {
      Pending p = pending.back();
      pending.pop_back();
      if (p.node < 0 || static_cast<size_t>(p.node) >= model.nodes.size())
        reader.Fail("node", std::to_string(p.node), "an existing node index");
      if (visited[p.node]) {
        reader.Fail("nodes[" + std::to_string(p.node) + "]", "reached twice",
                    "a tree: each node listed once, as a scene root or as one parent's child");
      }
      visited[p.node] = true;
      const tinygltf::Node& node = model.nodes[p.node];
      glm::dmat4 transform = p.parent * LocalTransform(node);
      if (node.mesh >= 0) AppendMesh(reader, model, node.mesh, transform, mesh);
      for (int child : node.children) pending.push_back({child, transform});
    }
  }
  if (mesh.indices.empty())
    reader.Fail("triangles", "0", "at least one triangle in the default scene");
  return mesh;
}

}  // namespace aerial
