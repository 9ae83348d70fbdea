#include "aerial/shader_abi/frame_block.h"

#include <glm/gtc/type_ptr.hpp>

namespace aerial {

std::array<float, 16> ToColumnMajorFloats(const glm::dmat4& m) {
  std::array<float, 16> out;
  const double* p = glm::value_ptr(m);
  for (int i = 0; i < 16; ++i) out[i] = float(p[i]);
  return out;
}

glm::dvec3 ViewRayFromScreen(const FrameUniforms& frame, glm::dvec2 uv) {
  glm::dmat4 inverse;  // column-major, as std140 stores it
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) inverse[column][row] = frame.inverse_view_projection[column * 4 + row];
  glm::dvec4 world = inverse * glm::dvec4(uv * 2.0 - 1.0, 0.5, 1.0);
  return glm::normalize(glm::dvec3(world) / world.w);
}

}  // namespace aerial
