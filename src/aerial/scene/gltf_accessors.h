#pragma once
// Typed reads of glTF accessors with every index and byte range checked, so a malformed file
// is an aerial::Error (where = the file's path) and never an out-of-bounds read.
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

#include "aerial/scene/tiny_gltf_config.h"

namespace aerial {

class GltfReader {
 public:
  GltfReader(const tinygltf::Model& model, std::string where)
      : model_(model), where_(std::move(where)) {}

  [[noreturn]] void Fail(const std::string& field, const std::string& value,
                         const std::string& allowed) const;

  // A float VEC3 accessor (POSITION, NORMAL). field names it in errors.
  std::vector<glm::dvec3> ReadVec3(int accessor_index, const std::string& field) const;

  // A SCALAR accessor of unsigned byte, short or int (triangle indices).
  std::vector<uint32_t> ReadIndices(int accessor_index, const std::string& field) const;

 private:
  const tinygltf::Accessor& Get(int index, const std::string& field) const;
  const unsigned char* Data(const tinygltf::Accessor& accessor, size_t element_size,
                            const std::string& field) const;
  size_t Stride(const tinygltf::Accessor& accessor) const;

  const tinygltf::Model& model_;
  std::string where_;
};

}  // namespace aerial
