#include "aerial/scene/gltf_parse_memory.h"

#include <string>

#include "aerial/core/input_limits.h"
#include "aerial/scene/tiny_gltf_config.h"

namespace aerial {
namespace {

// An element's cost: its struct three times (a std::vector's old and new storage while it grows,
// one more element than either) and what its members allocate on their own (a material's default
// colour factors, empty maps' and strings' first blocks, the allocator's headers).
template <typename T>
constexpr uint64_t ElementBytes() {
  return 3 * sizeof(T) + 256;
}

// What the elements of an array become, and how an object's members are read.
enum class Kind {
  kNone,  // plain JSON values: only their place in the trees
  kAccessor, kAnimation, kAnimationChannel, kAnimationSampler, kBuffer, kBufferView, kCamera,
  kImage, kLight, kMaterial, kMesh, kNode, kPrimitive, kSampler, kScene, kSkin, kTexture,
  kParameter,  // a material's member, kept again as a tinygltf::Parameter in a map
};

uint64_t KindBytes(Kind kind) {
  switch (kind) {
    case Kind::kNone: return 0;
    case Kind::kAccessor: return ElementBytes<tinygltf::Accessor>();
    case Kind::kAnimation: return ElementBytes<tinygltf::Animation>();
    case Kind::kAnimationChannel: return ElementBytes<tinygltf::AnimationChannel>();
    case Kind::kAnimationSampler: return ElementBytes<tinygltf::AnimationSampler>();
    case Kind::kBuffer: return ElementBytes<tinygltf::Buffer>();
    case Kind::kBufferView: return ElementBytes<tinygltf::BufferView>();
    case Kind::kCamera: return ElementBytes<tinygltf::Camera>();
    case Kind::kImage: return ElementBytes<tinygltf::Image>();
    case Kind::kLight: return ElementBytes<tinygltf::Light>();
    case Kind::kMaterial: return ElementBytes<tinygltf::Material>();
    case Kind::kMesh: return ElementBytes<tinygltf::Mesh>();
    case Kind::kNode: return ElementBytes<tinygltf::Node>();
    case Kind::kPrimitive: return ElementBytes<tinygltf::Primitive>();
    case Kind::kSampler: return ElementBytes<tinygltf::Sampler>();
    case Kind::kScene: return ElementBytes<tinygltf::Scene>();
    case Kind::kSkin: return ElementBytes<tinygltf::Skin>();
    case Kind::kTexture: return ElementBytes<tinygltf::Texture>();
    // A map node holds the key and the Parameter.
    case Kind::kParameter: return sizeof(tinygltf::Parameter) + sizeof(std::string) + 64;
  }
  return 0;
}

// Where an object stands in the glTF, which decides what its members become.
enum class Role { kOther, kRoot, kMesh, kAnimation, kMaterial, kPbr, kRootExtensions, kLights };

// A member `key` of an object of `role`: what its own members are read as (if an object), and what
// its elements become (if an array); and what the member itself costs besides its value.
struct Child {
  Role role = Role::kOther;
  Kind elements = Kind::kNone;
  Kind member = Kind::kNone;
};

Child ChildOf(Role role, std::string_view key) {
  struct Entry {
    Role role;
    std::string_view key;
    Child child;
  };
  static constexpr Entry kEntries[] = {
      {Role::kRoot, "accessors", {Role::kOther, Kind::kAccessor}},
      {Role::kRoot, "animations", {Role::kOther, Kind::kAnimation}},
      {Role::kRoot, "buffers", {Role::kOther, Kind::kBuffer}},
      {Role::kRoot, "bufferViews", {Role::kOther, Kind::kBufferView}},
      {Role::kRoot, "cameras", {Role::kOther, Kind::kCamera}},
      {Role::kRoot, "images", {Role::kOther, Kind::kImage}},
      {Role::kRoot, "materials", {Role::kOther, Kind::kMaterial}},
      {Role::kRoot, "meshes", {Role::kOther, Kind::kMesh}},
      {Role::kRoot, "nodes", {Role::kOther, Kind::kNode}},
      {Role::kRoot, "samplers", {Role::kOther, Kind::kSampler}},
      {Role::kRoot, "scenes", {Role::kOther, Kind::kScene}},
      {Role::kRoot, "skins", {Role::kOther, Kind::kSkin}},
      {Role::kRoot, "textures", {Role::kOther, Kind::kTexture}},
      {Role::kRoot, "extensions", {Role::kRootExtensions}},
      {Role::kRootExtensions, "KHR_lights_punctual", {Role::kLights}},
      {Role::kLights, "lights", {Role::kOther, Kind::kLight}},
      {Role::kMesh, "primitives", {Role::kOther, Kind::kPrimitive}},
      {Role::kAnimation, "channels", {Role::kOther, Kind::kAnimationChannel}},
      {Role::kAnimation, "samplers", {Role::kOther, Kind::kAnimationSampler}},
      {Role::kMaterial, "pbrMetallicRoughness", {Role::kPbr}},
  };
  for (const Entry& e : kEntries)
    if (e.role == role && e.key == key) return e.child;
  // Every other member of a material, and every member of its pbrMetallicRoughness, is also kept
  // as a Parameter (tinygltf's additionalValues and values), except those it reads apart.
  bool parameter = (role == Role::kMaterial && key != "name" && key != "extensions" && key != "extras") ||
                   role == Role::kPbr;
  return {Role::kOther, Kind::kNone, parameter ? Kind::kParameter : Kind::kNone};
}

// The role of an element of an array whose elements become `kind`.
Role ElementRole(Kind kind) {
  switch (kind) {
    case Kind::kMesh: return Role::kMesh;
    case Kind::kAnimation: return Role::kAnimation;
    case Kind::kMaterial: return Role::kMaterial;
    default: return Role::kOther;
  }
}

// A walk over the JSON text by its grammar, without checking it: a malformed text is the parser's
// to refuse, and it gets an estimate all the same. Recursion stops at kMaxJsonDepth levels
// whatever the text (the depth check made before refuses deeper ones anyway).
class Walk {
 public:
  explicit Walk(std::string_view json) : json_(json) {}

  uint64_t Run() {
    SkipSpace();
    if (at_ < json_.size()) Value(Role::kRoot, Kind::kNone);
    return bytes_;
  }

 private:
  void SkipSpace() {
    while (at_ < json_.size() && std::string_view(" \t\n\r").find(json_[at_]) != std::string_view::npos) ++at_;
  }

  // The string at at_ (a '"'), its escapes kept as written: keys are compared with plain names.
  std::string_view String() {
    size_t start = ++at_;
    while (at_ < json_.size() && json_[at_] != '"') at_ += json_[at_] == '\\' ? 2 : 1;
    std::string_view text = json_.substr(start, std::min(at_, json_.size()) - start);
    ++at_;
    return text;
  }

  // One value: an object's members are read as `role`, an array's elements become `elements`.
  void Value(Role role, Kind elements) {
    bytes_ += kGltfBytesPerValue;
    if (at_ >= json_.size()) return;
    char c = json_[at_];
    if ((c == '{' || c == '[') && depth_ < kMaxJsonDepth) {
      ++depth_;
      c == '{' ? Object(role) : Array(elements);
      --depth_;
    } else if (c == '"') {
      String();
    } else {
      // A number or a literal, up to what ends or starts a value.
      while (at_ < json_.size() && std::string_view(",:{}[]\" \t\n\r").find(json_[at_]) == std::string_view::npos)
        ++at_;
    }
  }

  // The members or elements of the object or array that opens at at_, each read by read(), up
  // to `close`.
  template <typename Read>
  void Items(char close, Read read) {
    ++at_;
    for (;;) {
      SkipSpace();
      if (at_ >= json_.size()) return;
      if (json_[at_] == close || json_[at_] == ',') {
        if (json_[at_++] == close) return;
        continue;
      }
      size_t before = at_;
      read();
      if (at_ == before) ++at_;  // a stray character: step over it
    }
  }

  void Object(Role role) {
    Items('}', [&] {
      std::string_view key = json_[at_] == '"' ? String() : std::string_view();
      SkipSpace();
      if (at_ < json_.size() && json_[at_] == ':') ++at_;
      SkipSpace();
      Child child = ChildOf(role, key);
      bytes_ += KindBytes(child.member);
      Value(child.role, child.elements);
    });
  }

  void Array(Kind elements) {
    Items(']', [&] {
      bytes_ += KindBytes(elements);
      Value(ElementRole(elements), Kind::kNone);
    });
  }

  std::string_view json_;
  size_t at_ = 0, depth_ = 0;
  uint64_t bytes_ = 0;
};

}  // namespace

uint64_t GltfParseBytes(std::string_view json, uint64_t file_bytes) {
  return Walk(json).Run() + file_bytes * kGltfBytesPerFileByte;
}

}  // namespace aerial
