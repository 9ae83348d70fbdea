#pragma once
// A ray cast against a scene's opaque meshes on the CPU, for checks of what the renderer draws:
// every triangle is tested (Moller and Trumbore 1997, "Fast, Minimum Storage Ray/Triangle
// Intersection"), in double precision from the meshes' float vertices. As the renderer draws them,
// transparent meshes are left out and the back faces of single-sided meshes are culled (scene.h).
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "aerial/scene.h"

namespace aerial {

struct MeshHit {
  double distance_m = 0.0;  // along the unit direction
  // The hit triangle's vertex normals and albedos interpolated at the hit (barycentric), the
  // normal made unit length and, on the back face of a double-sided mesh, turned to the side seen.
  glm::dvec3 normal{0.0}, albedo{0.0};
};

// The nearest hit in front of origin along the unit direction, if any.
std::optional<MeshHit> CastRay(const std::vector<Mesh>& meshes, const glm::dvec3& origin,
                               const glm::dvec3& direction);

}  // namespace aerial
