#pragma once
// Simple shapes appended to a mesh, built in double precision and stored as floats. Every shape
// has outward unit normals and counter-clockwise triangles seen from outside (scene.h).
#include <glm/glm.hpp>

#include "aerial/scene.h"

namespace aerial {

struct SurfaceLook {
  glm::vec3 albedo;
  float opacity = 1.0f;
};

// A box standing on base (its bottom face centered there), sides along the unit axes right and
// forward and height along up = right x forward. Flat-shaded: 24 vertices, 12 triangles.
void AppendBox(Mesh& mesh, const glm::dvec3& base, const glm::dvec3& right,
               const glm::dvec3& forward, const glm::dvec3& size_m, const SurfaceLook& look);

// A flat rectangle centered at center spanning width along the unit axis right and height along
// the unit axis up, split into columns x rows cells (so per-vertex shading samples it). Its normal
// is right x up; it has one side, and a renderer shows its back by disabling culling.
void AppendGrid(Mesh& mesh, const glm::dvec3& center, const glm::dvec3& right, const glm::dvec3& up,
                double width_m, double height_m, int columns, int rows, const SurfaceLook& look);

// A UV sphere with the poles on +-z: slices around, stacks pole to pole, smooth normals. The
// pole caps use one triangle per slice (no degenerate ones).
void AppendUvSphere(Mesh& mesh, const glm::dvec3& center, double radius_m, int slices, int stacks,
                    const SurfaceLook& look);

// A regular tetrahedron with circumradius radius_m, turned by rotation (orthonormal), flat
// shaded: 12 vertices, 4 triangles. It looks alike from every side, so particles made of them
// need no camera-facing orientation.
void AppendTetrahedron(Mesh& mesh, const glm::dvec3& center, double radius_m,
                       const glm::dmat3& rotation, const SurfaceLook& look);

}  // namespace aerial
