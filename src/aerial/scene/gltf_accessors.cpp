#include "aerial/scene/gltf_accessors.h"

#include <algorithm>
#include <cstring>

#include "aerial/error.h"

namespace aerial {
namespace {

std::string TypeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return std::to_string(type);
  }
}

std::string Indexed(const char* array, int index) {
  return std::string(array) + "[" + std::to_string(index) + "]";
}

}  // namespace

void GltfReader::Fail(const std::string& field, const std::string& value,
                      const std::string& allowed) const {
  throw Error(field, value, allowed, where_);
}

std::vector<glm::dvec3> GltfReader::ReadVec3(int accessor_index, const std::string& used_as) const {
  Elements e = Find(accessor_index, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                    "5126 (float)", used_as);
  std::vector<glm::dvec3> values(e.count);
  for (size_t i = 0; i < e.count; ++i) {
    float xyz[3];
    std::memcpy(xyz, e.first + i * e.stride, sizeof xyz);  // may be unaligned
    values[i] = {xyz[0], xyz[1], xyz[2]};
  }
  return values;
}

std::vector<uint32_t> GltfReader::ReadIndices(int accessor_index,
                                              const std::string& used_as) const {
  Elements e = Find(accessor_index, TINYGLTF_TYPE_SCALAR,
                    {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                    "5121, 5123 or 5125 (unsigned byte, short or int)", used_as);
  size_t size = static_cast<size_t>(
      tinygltf::GetComponentSizeInBytes(model_.accessors[accessor_index].componentType));
  std::vector<uint32_t> indices(e.count);
  for (size_t i = 0; i < e.count; ++i) {
    const unsigned char* p = e.first + i * e.stride;
    // glTF is little-endian, like the x86-64 and AArch64 machines this runs on.
    if (size == 1) indices[i] = p[0];
    if (size == 2) indices[i] = static_cast<uint32_t>(p[0] | p[1] << 8);
    if (size == 4) std::memcpy(&indices[i], p, 4);
  }
  return indices;
}

const tinygltf::Accessor& GltfReader::Get(int index, const std::string& used_as) const {
  if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size()) {
    Fail(used_as, "accessor " + std::to_string(index),
         "an accessor index below " + std::to_string(model_.accessors.size()));
  }
  const tinygltf::Accessor& a = model_.accessors[index];
  if (a.sparse.isSparse)
    Fail(Indexed("accessors", index) + ".sparse", "present", "a plain accessor");
  return a;
}

GltfReader::Elements GltfReader::Find(int index, int type, const std::vector<int>& component_types,
                                      const std::string& allowed_types,
                                      const std::string& used_as) const {
  const tinygltf::Accessor& a = Get(index, used_as);
  std::string field = Indexed("accessors", index);
  if (a.type != type)
    Fail(field + ".type", TypeName(a.type), TypeName(type) + " (read for " + used_as + ")");
  if (std::find(component_types.begin(), component_types.end(), a.componentType) ==
      component_types.end()) {
    Fail(field + ".componentType", std::to_string(a.componentType),
         allowed_types + " (read for " + used_as + ")");
  }
  size_t element_size = static_cast<size_t>(
      tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type)) *
      tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType)));
  Elements elements = Locate(index, element_size, used_as);
  tally_.Add(elements.count * kModelBytesPerElement);  // count < 2^32: it fits in the buffer
  return elements;
}

// The accessor's elements, after checking that all count elements of element_size bytes lie
// inside its buffer view and the view inside its buffer. The values come from the file and may
// be anything up to 2^64 - 1, so every bound is checked by subtracting from a size known to be
// larger, never by adding or multiplying them, which could wrap around.
GltfReader::Elements GltfReader::Locate(int index, size_t element_size,
                                        const std::string& used_as) const {
  const tinygltf::Accessor& a = model_.accessors[index];
  std::string field = Indexed("accessors", index);
  auto fail = [&](const std::string& bad_field, auto value, const std::string& allowed) {
    Fail(bad_field, std::to_string(value), allowed + " (read for " + used_as + ")");
  };
  if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= model_.bufferViews.size()) {
    fail(field + ".bufferView", a.bufferView,
         "a buffer view index below " + std::to_string(model_.bufferViews.size()));
  }
  const tinygltf::BufferView& view = model_.bufferViews[a.bufferView];
  std::string view_field = Indexed("bufferViews", a.bufferView);
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model_.buffers.size()) {
    fail(view_field + ".buffer", view.buffer,
         "a buffer index below " + std::to_string(model_.buffers.size()));
  }
  const std::vector<unsigned char>& buffer = model_.buffers[view.buffer].data;
  std::string buffer_field = Indexed("buffers", view.buffer);
  if (view.byteOffset > buffer.size()) {
    fail(view_field + ".byteOffset", view.byteOffset,
         "at most " + std::to_string(buffer.size()) + ", the size of " + buffer_field);
  }
  if (view.byteLength > buffer.size() - view.byteOffset) {
    fail(view_field + ".byteLength", view.byteLength,
         "at most " + std::to_string(buffer.size() - view.byteOffset) + ", the bytes of " +
             buffer_field + " after the view's byteOffset");
  }
  // tinygltf has checked that byteStride is 0 (tightly packed) or a multiple of 4 up to 252.
  size_t stride = view.byteStride == 0 ? element_size : view.byteStride;
  if (stride < element_size) {
    fail(view_field + ".byteStride", view.byteStride,
         "0 or at least " + std::to_string(element_size) + ", the bytes of an element of " + field);
  }
  if (a.byteOffset > view.byteLength) {
    fail(field + ".byteOffset", a.byteOffset,
         "at most " + std::to_string(view.byteLength) + ", the byteLength of " + view_field);
  }
  // count elements take (count - 1) * stride + element_size bytes.
  size_t room = view.byteLength - a.byteOffset;
  size_t max_count = room < element_size ? 0 : (room - element_size) / stride + 1;
  if (a.count > max_count) {
    fail(field + ".count", a.count,
         "at most " + std::to_string(max_count) + ", the elements of " +
             std::to_string(element_size) + " bytes every " + std::to_string(stride) +
             " bytes that fit in " + view_field + " after the accessor's byteOffset");
  }
  return {buffer.data() + view.byteOffset + a.byteOffset, stride, a.count};
}

}  // namespace aerial
