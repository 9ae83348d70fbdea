#pragma once
// Typed reads of glTF accessors with every index and byte range checked, so a malformed file
// is an aerial::Error (where = the file's path) and never an out-of-bounds read. Errors name the
// glTF's own field ("accessors[2].count", "bufferViews[0].byteOffset") and say which use of the
// accessor read it ("meshes[0].primitives[1].POSITION").
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

#include "aerial/core/memory_budget.h"
#include "aerial/scene/tiny_gltf_config.h"

namespace aerial {

// What reading one element costs, counted in the tally before its vector is allocated: a double
// vec3 (24 bytes) or an index (4), and a 40-byte vertex in the mesh, the GPU's buffer and its
// upload copy (an index gives one vertex when the model has no normals).
inline constexpr uint64_t kModelBytesPerElement = 24 + 3 * 40;

class GltfReader {
 public:
  GltfReader(const tinygltf::Model& model, std::string where, MemoryTally& tally)
      : model_(model), where_(std::move(where)), tally_(tally) {}

  [[noreturn]] void Fail(const std::string& field, const std::string& value,
                         const std::string& allowed) const;

  // A float VEC3 accessor (POSITION, NORMAL). used_as names the use in errors.
  std::vector<glm::dvec3> ReadVec3(int accessor_index, const std::string& used_as) const;

  // A SCALAR accessor of unsigned byte, short or int (triangle indices).
  std::vector<uint32_t> ReadIndices(int accessor_index, const std::string& used_as) const;

 private:
  // count elements, the first at first, one every stride bytes.
  struct Elements {
    const unsigned char* first;
    size_t stride;
    size_t count;
  };

  const tinygltf::Accessor& Get(int index, const std::string& used_as) const;
  // Checks the accessor's type and component type, then its bytes (Locate).
  Elements Find(int index, int type, const std::vector<int>& component_types,
                const std::string& allowed_types, const std::string& used_as) const;
  Elements Locate(int index, size_t element_size, const std::string& used_as) const;

  const tinygltf::Model& model_;
  std::string where_;
  MemoryTally& tally_;
};

}  // namespace aerial
