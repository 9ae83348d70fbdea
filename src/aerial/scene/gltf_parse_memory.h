#pragma once
// What parsing a glTF's JSON allocates, estimated from the text before tinygltf parses it, so
// that a model too big for the memory budget is refused before it is allocated
// (gltf_loader.h). A value costs its place in two trees (the JSON library's and tinygltf's), and
// an element of one of glTF's arrays (a material, a node, a mesh's primitive...) costs the
// struct tinygltf makes of it at its real size, however little the file spends on it: "{}" is two
// bytes of JSON and a tinygltf::Material of several hundred.
#include <cstdint>
#include <string_view>

namespace aerial {

// The bytes tinygltf's parse of json allocates at its peak, at most: per value
// kGltfBytesPerValue, per byte of the whole file (its text, strings and the buffers decoded from
// data URIs) kGltfBytesPerFileByte, and per element of a glTF array the struct it becomes, three
// times over (a growing std::vector holds its old and its new storage at once), with its members'
// own allocations; a material's members also become tinygltf::Parameters. file_bytes: the size of
// the .gltf or .glb file. json must nest at most kMaxJsonDepth levels (CheckJsonDepth first).
uint64_t GltfParseBytes(std::string_view json, uint64_t file_bytes);

// Each value is held twice, in the JSON library's tree and in tinygltf's (an `extras` array of 10
// million zeros, 20 MB, took 1.96 GB: 196 bytes a value); the text, its strings and the buffers
// decoded from data URIs take a few times the file's bytes.
inline constexpr uint64_t kGltfBytesPerValue = 200, kGltfBytesPerFileByte = 4;

}  // namespace aerial
