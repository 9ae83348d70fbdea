#include "aerial/scene/gltf_accessors.h"

#include <cstring>

#include "aerial/core/error.h"

namespace aerial {

void GltfReader::Fail(const std::string& field, const std::string& value,
                      const std::string& allowed) const {
  throw Error(field, value, allowed, where_);
}

std::vector<glm::dvec3> GltfReader::ReadVec3(int accessor_index, const std::string& field) const {
  const tinygltf::Accessor& a = Get(accessor_index, field);
  if (a.type != TINYGLTF_TYPE_VEC3 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
    Fail(field,
         "type " + std::to_string(a.type) + ", component type " + std::to_string(a.componentType),
         "float VEC3");
  }
  const unsigned char* data = Data(a, 3 * sizeof(float), field);
  size_t stride = Stride(a);
  std::vector<glm::dvec3> values(a.count);
  for (size_t i = 0; i < a.count; ++i) {
    float xyz[3];
    std::memcpy(xyz, data + i * stride, sizeof xyz);  // may be unaligned
    values[i] = {xyz[0], xyz[1], xyz[2]};
  }
  return values;
}

std::vector<uint32_t> GltfReader::ReadIndices(int accessor_index, const std::string& field) const {
  const tinygltf::Accessor& a = Get(accessor_index, field);
  size_t size = a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                : a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                : a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                            : 0;
  if (a.type != TINYGLTF_TYPE_SCALAR || size == 0) {
    Fail(field, "component type " + std::to_string(a.componentType),
         "SCALAR of unsigned byte, short or int");
  }
  const unsigned char* data = Data(a, size, field);
  size_t stride = Stride(a);
  std::vector<uint32_t> indices(a.count);
  for (size_t i = 0; i < a.count; ++i) {
    const unsigned char* p = data + i * stride;
    // glTF is little-endian, like the x86-64 and AArch64 machines this runs on.
    if (size == 1) indices[i] = p[0];
    if (size == 2) indices[i] = static_cast<uint32_t>(p[0] | p[1] << 8);
    if (size == 4) std::memcpy(&indices[i], p, 4);
  }
  return indices;
}

const tinygltf::Accessor& GltfReader::Get(int index, const std::string& field) const {
  if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size()) {
    Fail(field, "accessor " + std::to_string(index),
         "an accessor index below " + std::to_string(model_.accessors.size()));
  }
  const tinygltf::Accessor& a = model_.accessors[index];
  if (a.sparse.isSparse) Fail(field, "a sparse accessor", "a plain accessor");
  return a;
}

size_t GltfReader::Stride(const tinygltf::Accessor& a) const {
  return static_cast<size_t>(a.ByteStride(model_.bufferViews[a.bufferView]));
}

// The accessor's first element, after checking that all count elements of element_size bytes
// lie inside its buffer view and the view inside its buffer.
const unsigned char* GltfReader::Data(const tinygltf::Accessor& a, size_t element_size,
                                      const std::string& field) const {
  if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= model_.bufferViews.size())
    Fail(field + ".bufferView", std::to_string(a.bufferView), "an existing buffer view");
  const tinygltf::BufferView& view = model_.bufferViews[a.bufferView];
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model_.buffers.size())
    Fail(field + ".buffer", std::to_string(view.buffer), "an existing buffer");
  const tinygltf::Buffer& buffer = model_.buffers[view.buffer];
  int stride = a.ByteStride(view);  // -1 for an invalid type or misaligned byteStride
  if (stride < static_cast<int>(element_size))
    Fail(field + ".byteStride", std::to_string(stride), ">= the element size and aligned");
  size_t needed = a.count == 0 ? 0 : a.byteOffset + (a.count - 1) * stride + element_size;
  if (view.byteOffset + view.byteLength > buffer.data.size() || needed > view.byteLength) {
    Fail(field,
         std::to_string(a.count) + " elements from byte " +
             std::to_string(view.byteOffset + a.byteOffset),
         "data inside its buffer view and buffer (" + std::to_string(buffer.data.size()) +
             " bytes)");
  }
  return buffer.data.data() + view.byteOffset + a.byteOffset;
}

}  // namespace aerial
