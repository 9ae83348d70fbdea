// glTF meshes ([[mesh]] gltf = ...): the input is loaded as a .glb when it starts with the binary
// container's magic and as a .gltf (JSON) otherwise, as LoadGltfMesh decides by extension.
#include <cstring>

#include "aerial/error.h"
#include "aerial/scene/gltf_loader.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  auto path = aerial::fuzz::WriteInputFile(data, size, binary ? ".glb" : ".gltf");
  try {
    aerial::LoadGltfMesh(path, "fuzz");
  } catch (const aerial::Error&) {
  }
  return 0;
}
