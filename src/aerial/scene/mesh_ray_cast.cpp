#include "aerial/scene/mesh_ray_cast.h"

namespace aerial {
namespace {

// The hit of the ray with triangle (a, b, c) of mesh, if nearer than nearest.
void TestTriangle(const Mesh& mesh, const uint32_t* index, const glm::dvec3& origin,
                  const glm::dvec3& direction, std::optional<MeshHit>& nearest) {
  const Vertex &va = mesh.vertices[index[0]], &vb = mesh.vertices[index[1]], &vc = mesh.vertices[index[2]];
  glm::dvec3 a(va.position), e1 = glm::dvec3(vb.position) - a, e2 = glm::dvec3(vc.position) - a;
  glm::dvec3 p = glm::cross(direction, e2);
  // det = -direction . (e1 x e2): positive where the triangle is counter-clockwise seen from origin,
  // its front face.
  double det = glm::dot(e1, p);
  if (det == 0.0 || (det < 0.0 && !mesh.double_sided)) return;
  glm::dvec3 s = origin - a;
  double u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return;
  glm::dvec3 q = glm::cross(s, e1);
  double v = glm::dot(direction, q) / det;
  if (v < 0.0 || u + v > 1.0) return;
  double t = glm::dot(e2, q) / det;
  if (!(t > 0.0) || (nearest && t >= nearest->distance_m)) return;
  double w = 1.0 - u - v;
  glm::dvec3 normal = glm::normalize(w * glm::dvec3(va.normal) + u * glm::dvec3(vb.normal) + v * glm::dvec3(vc.normal));
  nearest = MeshHit{.distance_m = t,
                    .normal = det < 0.0 ? -normal : normal,
                    .albedo = w * glm::dvec3(va.albedo) + u * glm::dvec3(vb.albedo) + v * glm::dvec3(vc.albedo)};
}

}  // namespace

std::optional<MeshHit> CastRay(const std::vector<Mesh>& meshes, const glm::dvec3& origin,
                               const glm::dvec3& direction) {
  std::optional<MeshHit> nearest;
  for (const Mesh& mesh : meshes) {
    if (mesh.transparent) continue;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
      TestTriangle(mesh, &mesh.indices[i], origin, direction, nearest);
  }
  return nearest;
}

}  // namespace aerial
