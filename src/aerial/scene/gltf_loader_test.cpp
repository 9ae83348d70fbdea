#include "aerial/scene/gltf_loader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "aerial/error.h"

#ifndef AERIAL_SOURCE_DIR
#define AERIAL_SOURCE_DIR "."
#endif

namespace aerial {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

const fs::path kExamples = fs::path(AERIAL_SOURCE_DIR) / "examples/scenes";

// Positions are floats in the file and the transforms are exact in double (90-degree turns,
// powers of two), so 1e-5 m covers float rounding of coordinates up to ~100.
constexpr float kEps = 1e-5f;

std::string Base64(const std::vector<unsigned char>& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t group = bytes[i] << 16;
    if (i + 1 < bytes.size()) group |= bytes[i + 1] << 8;
    if (i + 2 < bytes.size()) group |= bytes[i + 2];
    for (size_t j = 0; j < 4; ++j)
      text += i + j <= bytes.size() ? kDigits[(group >> (18 - 6 * j)) & 63] : '=';
  }
  return text;
}

template <typename T>
void Append(std::vector<unsigned char>& blob, const std::vector<T>& values) {
  size_t at = blob.size();
  blob.resize(at + values.size() * sizeof(T));
  std::memcpy(blob.data() + at, values.data(), values.size() * sizeof(T));
}

// A unit cube centered on the origin, flat-shaded: 24 vertices, 12 counter-clockwise triangles
// (the layout of examples/scenes/make_cube_gltf.py). Its accessors are 0 POSITION, 1 NORMAL and
// 2 indices, in one buffer; the caller adds nodes, scenes, materials and the buffer's uri.
struct Document {
  json gltf;
  std::vector<unsigned char> blob;
};

Document CubeDocument(bool with_normals = true, int mode = 4) {
  const int faces[6][3][3] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}};
  std::vector<float> positions, normals;
  std::vector<uint16_t> indices;
  for (const auto& [n, u, v] : faces) {
    uint16_t first = static_cast<uint16_t>(positions.size() / 3);
    for (auto [su, sv] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
      for (int i = 0; i < 3; ++i) {
        positions.push_back(0.5f * (n[i] + su * u[i] + sv * v[i]));
        normals.push_back(static_cast<float>(n[i]));
      }
    }
    for (int k : {0, 1, 2, 0, 2, 3}) indices.push_back(static_cast<uint16_t>(first + k));
  }
  Document d;
  Append(d.blob, positions);
  Append(d.blob, normals);
  Append(d.blob, indices);
  size_t vertex_bytes = positions.size() * 4;
  json attributes = {{"POSITION", 0}};
  if (with_normals) attributes["NORMAL"] = 1;
  d.gltf = {{"asset", {{"version", "2.0"}}},
            {"meshes",
             {{{"primitives", {{{"attributes", attributes}, {"indices", 2}, {"mode", mode}}}}}}},
            {"accessors",
             {{{"bufferView", 0}, {"componentType", 5126}, {"count", 24}, {"type", "VEC3"}},
              {{"bufferView", 1}, {"componentType", 5126}, {"count", 24}, {"type", "VEC3"}},
              {{"bufferView", 2}, {"componentType", 5123}, {"count", 36}, {"type", "SCALAR"}}}},
            {"bufferViews",
             {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", vertex_bytes}},
              {{"buffer", 0}, {"byteOffset", vertex_bytes}, {"byteLength", vertex_bytes}},
              {{"buffer", 0}, {"byteOffset", 2 * vertex_bytes}, {"byteLength", 72}}}},
            {"buffers", {{{"byteLength", d.blob.size()}}}},
            {"scenes", {{{"nodes", {0}}}}},
            {"nodes", {{{"mesh", 0}}}}};
  return d;
}

class GltfFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / ("aerial_gltf_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path WriteText(const std::string& name, const std::string& text) {
    fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  // A .gltf with the buffer embedded as a data URI.
  fs::path WriteGltf(const std::string& name, Document d) {
    d.gltf["buffers"][0]["uri"] = "data:application/octet-stream;base64," + Base64(d.blob);
    return WriteText(name, d.gltf.dump());
  }
  // A .glb: 12-byte header, a JSON chunk padded with spaces and a BIN chunk padded with zeros
  // (glTF 2.0 spec, "Binary glTF Layout").
  fs::path WriteGlb(const std::string& name, const Document& d) {
    std::string text = d.gltf.dump();
    text.resize((text.size() + 3) / 4 * 4, ' ');
    std::vector<unsigned char> bin = d.blob;
    bin.resize((bin.size() + 3) / 4 * 4, 0);
    std::string out = "glTF";
    auto u32 = [&](uint32_t value) { out.append(reinterpret_cast<const char*>(&value), 4); };
    u32(2);
    u32(static_cast<uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
    u32(static_cast<uint32_t>(text.size()));
    u32(0x4E4F534A);  // "JSON"
    out += text;
    u32(static_cast<uint32_t>(bin.size()));
    u32(0x004E4942);  // "BIN\0"
    out.append(bin.begin(), bin.end());
    return WriteText(name, out);
  }

  fs::path dir_;
};

void ExpectBounds(const Mesh& mesh, glm::vec3 low, glm::vec3 high) {
  glm::vec3 min(HUGE_VALF), max(-HUGE_VALF);
  for (const Vertex& v : mesh.vertices) {
    min = glm::min(min, v.position);
    max = glm::max(max, v.position);
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(min[i], low[i], kEps) << "axis " << i;
    EXPECT_NEAR(max[i], high[i], kEps) << "axis " << i;
  }
}

// Every triangle's winding agrees with its vertex normals, which are unit length.
void ExpectConsistentNormals(const Mesh& mesh) {
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    const Vertex &a = mesh.vertices[mesh.indices[i]], &b = mesh.vertices[mesh.indices[i + 1]],
                 &c = mesh.vertices[mesh.indices[i + 2]];
    glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
    for (const Vertex* v : {&a, &b, &c}) {
      EXPECT_NEAR(glm::length(v->normal), 1.0f, 1e-6f);
      EXPECT_GT(glm::dot(face, v->normal), 0.0f) << "triangle " << i / 3;
    }
  }
}

TEST(GltfLoader, ExampleCubeHas12TrianglesAndItsNodeTransform) {
  Mesh mesh = LoadGltfMesh(kExamples / "cube.gltf", "cube");
  EXPECT_EQ(mesh.name, "cube");
  EXPECT_EQ(mesh.indices.size(), 36u);
  EXPECT_EQ(mesh.vertices.size(), 24u);
  EXPECT_FALSE(mesh.transparent);
  // The node scales the unit cube by 10 and lifts it 5 along glTF's up (+y), which becomes +z.
  ExpectBounds(mesh, {-5, -5, 0}, {5, 5, 10});
  ExpectConsistentNormals(mesh);
  for (const Vertex& v : mesh.vertices) {
    EXPECT_EQ(v.albedo, glm::vec3(0.6f, 0.25f, 0.12f));  // baseColorFactor, as written
    EXPECT_EQ(v.opacity, 1.0f);
  }
}

TEST(GltfLoader, MissingFileErrorNamesThePath) {
  fs::path path = kExamples / "no-such-model.glb";
  try {
    LoadGltfMesh(path, "x");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.value(), path.string());
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos);
  }
}

TEST_F(GltfFiles, ParseErrorNamesThePath) {
  fs::path path = WriteText("broken.gltf", "{ \"asset\": ");
  try {
    LoadGltfMesh(path, "x");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.value(), path.string());
  }
}

TEST_F(GltfFiles, BinaryGlbLoads) {
  Mesh mesh = LoadGltfMesh(WriteGlb("cube.glb", CubeDocument()), "cube");
  EXPECT_EQ(mesh.indices.size(), 36u);
  ExpectBounds(mesh, {-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f});
  ExpectConsistentNormals(mesh);
}

TEST_F(GltfFiles, MissingNormalsBecomeFaceNormals) {
  Mesh mesh = LoadGltfMesh(WriteGltf("flat.gltf", CubeDocument(/*with_normals=*/false)), "flat");
  EXPECT_EQ(mesh.indices.size(), 36u);
  EXPECT_EQ(mesh.vertices.size(), 36u);  // each triangle has its own vertices
  ExpectConsistentNormals(mesh);
  for (const Vertex& v : mesh.vertices) {  // a cube's face normals are axis-aligned
    EXPECT_NEAR(std::fabs(v.normal.x) + std::fabs(v.normal.y) + std::fabs(v.normal.z), 1.0f, kEps);
  }
}

TEST_F(GltfFiles, OnlyTrianglesAreAccepted) {
  fs::path path = WriteGltf("lines.gltf", CubeDocument(true, /*LINES*/ 1));
  try {
    LoadGltfMesh(path, "lines");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "meshes[0].primitives[0].mode");
    EXPECT_NE(e.value().find("LINES"), std::string::npos);
    EXPECT_EQ(e.where(), path.string());
  }
}

TEST_F(GltfFiles, NodeHierarchyComposesTransforms) {
  // One triangle (1,0,0), (0,2,0), (0,0,3) in a child node scaled by 2 (as a matrix), under a
  // parent turned +90 degrees about glTF's y and moved 100 along x. By hand: scale, then
  // (x, y, z) -> (z, y, -x), then +100 x, then the z-up change (x, y, z) -> (x, -z, y).
  Document d = CubeDocument(false);
  std::vector<float> triangle = {1, 0, 0, 0, 2, 0, 0, 0, 3};
  d.blob.clear();
  Append(d.blob, triangle);
  d.gltf["accessors"] = {
      {{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}};
  d.gltf["bufferViews"] = {{{"buffer", 0}, {"byteLength", 36}}};
  d.gltf["buffers"] = {{{"byteLength", 36}}};
  d.gltf["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}};
  const double h = std::sqrt(0.5);
  d.gltf["nodes"] = {{{"children", {1}}, {"rotation", {0, h, 0, h}}, {"translation", {100, 0, 0}}},
                     {{"mesh", 0}, {"matrix", {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1}}}};
  Mesh mesh = LoadGltfMesh(WriteGltf("tree.gltf", d), "tree");
  ASSERT_EQ(mesh.vertices.size(), 3u);
  const glm::vec3 expected[3] = {{100, 2, 0}, {100, 0, 4}, {106, 0, 0}};
  for (int i = 0; i < 3; ++i) {
    glm::vec3 p = mesh.vertices[mesh.indices[i]].position;
    EXPECT_NEAR(glm::distance(p, expected[i]), 0.0f, kEps) << i;
  }
}

TEST_F(GltfFiles, MirroringTransformKeepsTrianglesFacingOut) {
  Document d = CubeDocument();
  d.gltf["nodes"][0]["scale"] = {-1, 1, 1};
  Mesh mesh = LoadGltfMesh(WriteGltf("mirror.gltf", d), "mirror");
  ExpectConsistentNormals(mesh);
  for (const Vertex& v : mesh.vertices)  // still outward
    EXPECT_GT(glm::dot(v.normal, v.position), 0.0f);
}

TEST_F(GltfFiles, BlendMaterialMakesATransparentMesh) {
  Document d = CubeDocument();
  d.gltf["materials"] = {{{"alphaMode", "BLEND"},
                          {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.8, 0.5}}}}}};
  d.gltf["meshes"][0]["primitives"][0]["material"] = 0;
  Mesh mesh = LoadGltfMesh(WriteGltf("glass.gltf", d), "glass");
  EXPECT_TRUE(mesh.transparent);
  for (const Vertex& v : mesh.vertices) {
    EXPECT_EQ(v.opacity, 0.5f);
    EXPECT_EQ(v.albedo, glm::vec3(0.2f, 0.4f, 0.8f));
  }
}

TEST_F(GltfFiles, TexturedModelLoadsWithoutDecodingImages) {
  Document d = CubeDocument();
  d.gltf["images"] = {{{"uri", "data:image/png;base64,iVBORw0KGgo="}}};
  d.gltf["textures"] = {{{"source", 0}}};
  d.gltf["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  d.gltf["meshes"][0]["primitives"][0]["material"] = 0;
  Mesh mesh = LoadGltfMesh(WriteGltf("textured.gltf", d), "textured");
  EXPECT_EQ(mesh.indices.size(), 36u);
}

TEST_F(GltfFiles, SceneWithoutTrianglesIsAnError) {
  Document d = CubeDocument();
  // json::array: a braced list of one object reads as that object with clang.
  d.gltf["nodes"] = json::array({json::object()});  // a node without a mesh
  fs::path path = WriteGltf("empty.gltf", d);
  try {
    LoadGltfMesh(path, "empty");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "triangles");
    EXPECT_EQ(e.where(), path.string());
  }
}

TEST_F(GltfFiles, OutOfRangeIndexIsAnError) {
  Document d = CubeDocument();
  uint16_t bad = 24;  // one past the last vertex
  std::memcpy(d.blob.data() + 2 * 24 * 12, &bad, 2);
  EXPECT_THROW(LoadGltfMesh(WriteGltf("bad.gltf", d), "bad"), Error);
}

}  // namespace
}  // namespace aerial
