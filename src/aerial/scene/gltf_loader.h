#pragma once
// glTF 2.0 models (.gltf with embedded or external buffers, or .glb) as one Mesh in the world
// frame's axes (scene.h).
//
// Everything the default scene (or scene 0, or with no scenes every mesh once) draws is merged:
// all primitives of all meshes of its nodes, each node's transform (matrix, or translation x
// rotation x scale) composed down the hierarchy. glTF is y-up with models facing +z; it is turned
// to z-up by (x, y, z) -> (x, -z, y), a rotation, so up becomes +z and a model's front faces -y
// (toward a camera looking north at it).
//
// Only what a Lambertian, per-vertex renderer uses is read: POSITION (required, float vec3),
// NORMAL (float vec3; when absent, each triangle gets its face normal, so hard edges stay hard)
// and the material's baseColorFactor (linear RGB by the glTF spec) as albedo, its alpha as
// opacity when alphaMode is BLEND (then the mesh is transparent) and 1 otherwise. Textures,
// vertex colors, skins and morph targets are ignored. Only TRIANGLES primitives are accepted.
//
// Errors throw aerial::Error with the path as where: a missing, unparsable or non-regular file,
// a model whose files hold more than kMaxGltfBytes together or whose JSON nests deeper than
// kMaxJsonDepth (core/input_limits.h), a primitive of another mode (naming it), a missing
// POSITION, data outside its buffer (naming the glTF field, "accessors[2].count"), a buffer file
// outside the model's folder (gltf_file_system.h), a node reached twice (the nodes must form a
// tree), a vertex that is not finite or lies beyond kMaxModelCoordinateM after the node
// transforms, a model whose memory would exceed the budget, or no triangles at all.
#include <filesystem>
#include <string>

#include "aerial/core/memory_budget.h"
#include "aerial/scene.h"

namespace aerial {

// budget: the host memory the model may take while it loads, estimated before each allocation
// (its JSON parse, then each accessor read); by default the default budget (memory_budget.h).
Mesh LoadGltfMesh(const std::filesystem::path& path, const std::string& name,
                  const MemoryBudget& budget = MakeMemoryBudget(std::nullopt, UINT64_MAX));

// What a loaded mesh holds while the command runs, as its load counted it: its vertices and
// indices (by their vectors' capacity) in the mesh, the GPU's buffers and their upload copies.
uint64_t HeldMeshBytes(const Mesh& mesh);

}  // namespace aerial
