#pragma once
// Camera frame and matrices in the world frame of scene.h (x east, y north, z up).
//
// View space is right-handed, x right, y up, and the camera looks down -z (the OpenGL/glm
// convention). Clip space is Vulkan's: x right, y down, depth in [0, 1].
#include <vector>

#include <glm/glm.hpp>

#include "aerial/scene.h"

namespace aerial {

// The unit vector at zenith angle zenith_deg from +z and compass azimuth azimuth_deg:
// (sin z sin a, sin z cos a, cos z). Shared by the sun and the camera (zenith = 90 - pitch).
glm::dvec3 DirectionFromZenithAzimuth(double zenith_deg, double azimuth_deg);

// The camera's orthonormal basis. Forward = DirectionFromZenithAzimuth(90 - pitch, yaw). Right is
// horizontal, (cos yaw, -sin yaw, 0), so it stays defined looking straight up or down, and
// Up = Right x Forward completes a right-handed frame (Right x Up = -Forward).
glm::dvec3 Forward(const Camera& camera);
glm::dvec3 Right(const Camera& camera);
glm::dvec3 Up(const Camera& camera);

// World -> view: rows Right, Up, -Forward, then the translation by -position.
glm::dmat4 ViewMatrix(const Camera& camera);

// View -> Vulkan clip space with reversed Z and no far plane. With f = 1 / tan(fov / 2):
//   clip = (f / aspect * x, -f * y, near, -z)
// so depth = near / -z: 1 at the near plane, falling toward 0 at infinity. Reversed Z spends the
// float's dense exponent range near 0 on far geometry, which keeps 100 km mountains and a pane
// 300 m away depth-separable at 32 bits; clear depth to 0 and test with GREATER. The y flip makes
// world up point to the top of a Vulkan framebuffer. aspect = width / height.
glm::dmat4 ProjectionMatrix(const Camera& camera, double aspect);

// The jitters (Camera::jitter_px) that supersample a frame n x n: the centres of each pixel's
// n x n sub-pixels, about the pixel's centre, row by row. The mean of the frames drawn with them
// samples what a frame n times larger on each side, box-filtered down, samples, while each
// frame keeps the output's resolution for what is chosen per pixel (the terrain's level of
// detail, the ground's detail: shaders/include/ground_detail.glsl).
std::vector<glm::dvec2> SupersampleJitters(int n);

}  // namespace aerial
