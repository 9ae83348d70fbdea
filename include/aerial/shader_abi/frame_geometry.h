#pragma once
// The CPU twins of what the shaders compute from the FrameBlock (aerial/shader_abi/frame_block.h):
// the ray through a pixel, for a check that traces the pixels a renderer drew.
#include <array>

#include <glm/glm.hpp>

#include "aerial/shader_abi/frame_block.h"

namespace aerial {

// The view ray through the screen point uv ((0, 0) top-left), as frame.glsl computes it.
glm::dvec3 ViewRayFromScreen(const FrameUniforms& frame, glm::dvec2 uv);

std::array<float, 16> ToColumnMajorFloats(const glm::dmat4& m);
// The inverse: a matrix as the FrameBlock stores it (column-major, std140).
glm::dmat4 FromColumnMajorFloats(const std::array<float, 16>& m);

}  // namespace aerial
