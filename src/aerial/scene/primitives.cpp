#include "aerial/scene/primitives.h"

#include <cmath>
#include <numbers>

namespace aerial {
namespace {

uint32_t AddVertex(Mesh& mesh, const glm::dvec3& position, const glm::dvec3& normal,
                   const SurfaceLook& look) {
  mesh.vertices.push_back(
      {glm::vec3(position), glm::vec3(glm::normalize(normal)), look.albedo, look.opacity});
  return static_cast<uint32_t>(mesh.vertices.size() - 1);
}

// A flat triangle with its own three vertices, so its normal is the face normal.
void AddFlatTriangle(Mesh& mesh, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                     const SurfaceLook& look) {
  glm::dvec3 normal = glm::cross(b - a, c - a);
  for (const glm::dvec3* p : {&a, &b, &c})
    mesh.indices.push_back(AddVertex(mesh, *p, normal, look));
}

// A quad a, b, c, d counter-clockwise seen from its front, with its own four vertices.
void AddFlatQuad(Mesh& mesh, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                 const glm::dvec3& d, const SurfaceLook& look) {
  glm::dvec3 normal = glm::cross(b - a, d - a);
  uint32_t first = static_cast<uint32_t>(mesh.vertices.size());
  for (const glm::dvec3* p : {&a, &b, &c, &d}) AddVertex(mesh, *p, normal, look);
  mesh.indices.insert(mesh.indices.end(),
                      {first, first + 1, first + 2, first, first + 2, first + 3});
}

}  // namespace

void AppendBox(Mesh& mesh, const glm::dvec3& base, const glm::dvec3& right,
               const glm::dvec3& forward, const glm::dvec3& size_m, const SurfaceLook& look) {
  glm::dvec3 up = glm::cross(right, forward);
  glm::dvec3 x = right * (size_m.x / 2), y = forward * (size_m.y / 2), z = up * size_m.z;
  // Corners: bottom (b) and top (t), then the signs of x and y.
  glm::dvec3 b00 = base - x - y, b10 = base + x - y, b11 = base + x + y, b01 = base - x + y;
  glm::dvec3 t00 = b00 + z, t10 = b10 + z, t11 = b11 + z, t01 = b01 + z;
  AddFlatQuad(mesh, b00, b01, b11, b10, look);  // bottom, facing -up
  AddFlatQuad(mesh, t00, t10, t11, t01, look);  // top
  AddFlatQuad(mesh, b00, b10, t10, t00, look);  // facing -forward
  AddFlatQuad(mesh, b10, b11, t11, t10, look);  // facing +right
  AddFlatQuad(mesh, b11, b01, t01, t11, look);  // facing +forward
  AddFlatQuad(mesh, b01, b00, t00, t01, look);  // facing -right
}

void AppendGrid(Mesh& mesh, const glm::dvec3& center, const glm::dvec3& right, const glm::dvec3& up,
                double width_m, double height_m, int columns, int rows, const SurfaceLook& look) {
  glm::dvec3 normal = glm::cross(right, up);
  uint32_t first = static_cast<uint32_t>(mesh.vertices.size());
  for (int row = 0; row <= rows; ++row) {
    for (int column = 0; column <= columns; ++column) {
      double u = static_cast<double>(column) / columns - 0.5;
      double v = static_cast<double>(row) / rows - 0.5;
      AddVertex(mesh, center + right * (u * width_m) + up * (v * height_m), normal, look);
    }
  }
  auto at = [&](int column, int row) {
    return first + static_cast<uint32_t>(row * (columns + 1) + column);
  };
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      uint32_t a = at(column, row), b = at(column + 1, row);
      uint32_t c = at(column + 1, row + 1), d = at(column, row + 1);
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  }
}

void AppendUvSphere(Mesh& mesh, const glm::dvec3& center, double radius_m, int slices, int stacks,
                    const SurfaceLook& look) {
  uint32_t first = static_cast<uint32_t>(mesh.vertices.size());
  // Rows from the north pole (stack 0) to the south pole (stack = stacks), slices + 1 columns
  // so the seam has its own vertices.
  for (int stack = 0; stack <= stacks; ++stack) {
    double polar = std::numbers::pi * stack / stacks;
    for (int slice = 0; slice <= slices; ++slice) {
      double azimuth = 2.0 * std::numbers::pi * slice / slices;
      glm::dvec3 n{std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                   std::cos(polar)};
      AddVertex(mesh, center + radius_m * n, n, look);
    }
  }
  auto at = [&](int stack, int slice) {
    return first + static_cast<uint32_t>(stack * (slices + 1) + slice);
  };
  // Azimuth grows counter-clockwise seen from +z, and stacks go down: a, b (next slice), c
  // (below b), d (below a) is counter-clockwise seen from outside.
  for (int stack = 0; stack < stacks; ++stack) {
    for (int slice = 0; slice < slices; ++slice) {
      uint32_t a = at(stack, slice), b = at(stack, slice + 1);
      uint32_t c = at(stack + 1, slice + 1), d = at(stack + 1, slice);
      if (stack > 0) mesh.indices.insert(mesh.indices.end(), {a, d, b});
      if (stack + 1 < stacks) mesh.indices.insert(mesh.indices.end(), {b, d, c});
    }
  }
}

void AppendTetrahedron(Mesh& mesh, const glm::dvec3& center, double radius_m,
                       const glm::dmat3& rotation, const SurfaceLook& look) {
  // Alternate corners of a cube: each is at distance sqrt(3) from the center.
  const double s = radius_m / std::sqrt(3.0);
  glm::dvec3 p[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (glm::dvec3& corner : p) corner = center + rotation * (corner * s);
  // Each face omits one corner; the order is chosen so the face normal points away from it.
  AddFlatTriangle(mesh, p[1], p[3], p[2], look);
  AddFlatTriangle(mesh, p[0], p[2], p[3], look);
  AddFlatTriangle(mesh, p[0], p[3], p[1], look);
  AddFlatTriangle(mesh, p[0], p[1], p[2], look);
}

}  // namespace aerial
