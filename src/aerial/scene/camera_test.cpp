#include "aerial/scene/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include <glm/gtc/type_ptr.hpp>

#include "aerial/froxels.h"
#include "aerial/scene.h"

namespace aerial {
namespace {

// Matrices are doubles built from sines and cosines of the angles: results are exact to a few
// ulps, so 1e-9 is a tolerance for rounding, not for approximation.
constexpr double kEps = 1e-9;

glm::dvec3 Ndc(const Camera& camera, double aspect, const glm::dvec3& world) {
  glm::dvec4 clip = ProjectionMatrix(camera, aspect) * ViewMatrix(camera) * glm::dvec4(world, 1);
  return glm::dvec3(clip) / clip.w;
}

Camera Tilted(double yaw, double pitch) {
  Camera camera;
  camera.position = {1200.0, -300.0, 45.0};
  camera.yaw_deg = yaw;
  camera.pitch_deg = pitch;
  camera.vertical_fov_deg = 50.0;
  camera.near_m = 0.5;
  return camera;
}

TEST(CameraMatrices, PointStraightAheadProjectsToImageCenter) {
  for (double yaw : {0.0, 37.0, 90.0, 200.0, -45.0}) {
    for (double pitch : {-90.0, -30.0, 0.0, 4.0, 89.0, 90.0}) {
      Camera camera = Tilted(yaw, pitch);
      glm::dvec3 ndc = Ndc(camera, 16.0 / 9.0, camera.position + 5000.0 * Forward(camera));
      EXPECT_NEAR(ndc.x, 0.0, kEps) << "yaw " << yaw << " pitch " << pitch;
      EXPECT_NEAR(ndc.y, 0.0, kEps) << "yaw " << yaw << " pitch " << pitch;
    }
  }
}

TEST(CameraMatrices, ReversedZPutsFarPointsAtSmallerDepth) {
  Camera camera = Tilted(30.0, 5.0);
  auto depth = [&](double distance) {
    return Ndc(camera, 1.5, camera.position + distance * Forward(camera)).z;
  };
  EXPECT_NEAR(depth(camera.near_m), 1.0, kEps);  // the near plane maps to 1
  double previous = depth(camera.near_m);
  for (double distance : {1.0, 30.0, 300.0, 1e4, 1e5, 1e7}) {
    double d = depth(distance);
    EXPECT_LT(d, previous) << distance;
    EXPECT_GT(d, 0.0) << distance;  // no far plane: nothing is clipped at depth 0
    EXPECT_NEAR(d, camera.near_m / distance, kEps) << distance;
    previous = d;
  }
}

TEST(CameraMatrices, UpIsTopAndRightIsRightInVulkanClipSpace) {
  Camera camera = Tilted(120.0, -10.0);
  glm::dvec3 ahead = camera.position + 100.0 * Forward(camera);
  EXPECT_LT(Ndc(camera, 1.0, ahead + 10.0 * Up(camera)).y, 0.0);  // Vulkan's y points down
  EXPECT_GT(Ndc(camera, 1.0, ahead + 10.0 * Right(camera)).x, 0.0);
}

TEST(CameraMatrices, FieldOfViewEdgesMapToNdcEdges) {
  Camera camera = Tilted(10.0, 20.0);
  double half = camera.vertical_fov_deg / 2.0 * std::numbers::pi / 180.0, aspect = 16.0 / 9.0;
  glm::dvec3 top = Forward(camera) * std::cos(half) + Up(camera) * std::sin(half);
  EXPECT_NEAR(Ndc(camera, aspect, camera.position + 700.0 * top).y, -1.0, kEps);
  // Horizontally the half-width is aspect * tan(fov / 2) at unit distance.
  glm::dvec3 side = Forward(camera) + Right(camera) * (aspect * std::tan(half));
  EXPECT_NEAR(Ndc(camera, aspect, camera.position + 700.0 * side).x, 1.0, kEps);
}

TEST(CameraBasis, OrthonormalRightHandedWithHorizontalRight) {
  for (double pitch : {-90.0, -5.0, 0.0, 60.0, 90.0}) {
    Camera camera = Tilted(250.0, pitch);
    glm::dvec3 f = Forward(camera), r = Right(camera), u = Up(camera);
    EXPECT_NEAR(glm::length(f), 1.0, kEps);
    EXPECT_NEAR(glm::length(r), 1.0, kEps);
    EXPECT_NEAR(glm::length(u), 1.0, kEps);
    EXPECT_NEAR(glm::dot(f, r), 0.0, kEps);
    EXPECT_NEAR(glm::dot(f, u), 0.0, kEps);
    EXPECT_NEAR(r.z, 0.0, kEps);  // no roll
    EXPECT_NEAR(glm::distance(glm::cross(r, u), -f), 0.0, kEps);
    EXPECT_GE(u.z, -kEps);  // the image is never upside down
  }
}

TEST(CameraBasis, YawIsCompassAzimuthAndPitchIsElevation) {
  Camera camera;
  camera.yaw_deg = 0.0;
  EXPECT_NEAR(glm::distance(Forward(camera), glm::dvec3(0, 1, 0)), 0.0, kEps);  // north
  camera.yaw_deg = 90.0;
  EXPECT_NEAR(glm::distance(Forward(camera), glm::dvec3(1, 0, 0)), 0.0, kEps);  // east
  camera.pitch_deg = 30.0;
  EXPECT_NEAR(Forward(camera).z, 0.5, kEps);  // sin 30
}

TEST(CameraView, MapsCameraToOriginAndForwardToMinusZ) {
  Camera camera = Tilted(75.0, 12.0);
  glm::dmat4 view = ViewMatrix(camera);
  glm::dvec4 eye = view * glm::dvec4(camera.position, 1.0);
  EXPECT_NEAR(glm::length(glm::dvec3(eye)), 0.0, 1e-9 * glm::length(camera.position));
  glm::dvec4 forward = view * glm::dvec4(Forward(camera), 0.0);
  EXPECT_NEAR(glm::distance(glm::dvec3(forward), glm::dvec3(0, 0, -1)), 0.0, kEps);
}

// The frame's pixel coordinates (x right, y down, pixel centres at half integers) of a point.
glm::dvec2 FramePixel(const FrameCamera& frame, const glm::dvec3& relative) {
  glm::dvec4 clip = glm::make_mat4(frame.view_projection.data()) * glm::dvec4(relative, 1.0);
  return {(clip.x / clip.w + 1.0) * 0.5 * frame.width, (clip.y / clip.w + 1.0) * 0.5 * frame.height};
}

// A jittered frame shows at pixel c what the unjittered one shows at c + jitter: every point moves
// by -jitter pixels, wherever it is in the frame.
TEST(CameraJitter, MovesTheImageByMinusTheJitterInPixels) {
  Scene scene;
  scene.camera = Tilted(37.0, 4.0);
  const glm::dvec2 jitter{0.25, -0.375};
  Scene jittered = scene;
  jittered.camera.jitter_px = jitter;
  FrameCamera plain = MakeFrameCamera(scene, 160, 90), moved = MakeFrameCamera(jittered, 160, 90);
  Camera& camera = scene.camera;
  for (glm::dvec3 direction : {Forward(camera), Forward(camera) + 0.3 * Right(camera) - 0.2 * Up(camera),
                               Forward(camera) - 0.5 * Right(camera) + 0.25 * Up(camera)}) {
    for (double distance : {3.0, 900.0, 4.0e4}) {
      glm::dvec2 shift = FramePixel(moved, distance * direction) - FramePixel(plain, distance * direction);
      EXPECT_NEAR(shift.x, -jitter.x, 1e-9) << distance;  // doubles: rounding only (kEps)
      EXPECT_NEAR(shift.y, -jitter.y, 1e-9) << distance;
    }
  }
}

TEST(CameraSun, DirectionFollowsZenithAndCompassAzimuth) {
  EXPECT_NEAR(glm::distance(Sun{0.0, 123.0}.Direction(), glm::dvec3(0, 0, 1)), 0.0, kEps);
  EXPECT_NEAR(glm::distance(Sun{90.0, 0.0}.Direction(), glm::dvec3(0, 1, 0)), 0.0, kEps);
  EXPECT_NEAR(glm::distance(Sun{90.0, 90.0}.Direction(), glm::dvec3(1, 0, 0)), 0.0, kEps);
  EXPECT_LT((Sun{96.0, 270.0}.Direction().z), 0.0);  // set
  EXPECT_LT((Sun{96.0, 270.0}.Direction().x), 0.0);  // in the west
}

// The jitters of an n x n supersampled pixel are the centres of its sub-pixels, each once: for
// n = 2 the quadrants' centres at +-1/4, for n = 3 the offsets -1/3, 0 and 1/3; their mean is the
// pixel's centre.
TEST(SupersampleJitters, AreTheCentresOfEachSubPixel) {
  EXPECT_EQ(SupersampleJitters(1), std::vector<glm::dvec2>{glm::dvec2(0.0)});
  for (int n : {2, 3, 4}) {
    std::vector<glm::dvec2> jitters = SupersampleJitters(n);
    ASSERT_EQ(jitters.size(), size_t(n * n));
    glm::dvec2 sum(0.0);
    std::set<std::pair<double, double>> distinct;
    for (glm::dvec2 j : jitters) {
      sum += j;
      distinct.insert({j.x, j.y});
      for (double c : {j.x, j.y}) {
        double sub_pixel = (c + 0.5) * n - 0.5;  // 0 .. n - 1 at the sub-pixels' centres
        EXPECT_NEAR(sub_pixel, std::round(sub_pixel), 1e-12) << n;
        EXPECT_GT(c, -0.5);
        EXPECT_LT(c, 0.5);
      }
    }
    EXPECT_EQ(distinct.size(), size_t(n * n)) << n;
    EXPECT_NEAR(sum.x, 0.0, 1e-12) << n;
    EXPECT_NEAR(sum.y, 0.0, 1e-12) << n;
  }
  EXPECT_DOUBLE_EQ(SupersampleJitters(2)[0].x, -0.25);
}

}  // namespace
}  // namespace aerial
