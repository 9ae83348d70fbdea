// The built-in scene: everything a first render needs to show aerial perspective with no input.
// Stone landmarks of one albedo stand at 1 to 40 km so that only the air between them and the
// camera tells their brightness apart; transparent objects at 300 m to 8 km check that blended
// surfaces are attenuated and in-scattered like opaque ones; mountains 5-80 km away fade into the sky.
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <numbers>
#include <string>

#include "aerial/scene/noise.h"
#include "aerial/scene.h"
#include "aerial/scene/primitives.h"
#include "aerial/scene/terrain.h"

namespace aerial {
namespace {

// The default camera stands at the origin looking north (presets.cpp); objects are placed by
// horizontal distance and compass azimuth from there, all within its +-40 degree horizontal field
// of view at 16:9 and spread in azimuth so that no landmark hides another.
struct Placement {
  double distance_m, azimuth_deg;
};

glm::dvec2 Horizontal(const Placement& at) {
  double azimuth = at.azimuth_deg * std::numbers::pi / 180.0;
  return {at.distance_m * std::sin(azimuth), at.distance_m * std::cos(azimuth)};
}

// The horizontal unit vector from the origin toward at, in the tangent plane of frame.
glm::dvec3 AwayFromCamera(const GroundFrame& frame) {
  glm::dvec3 toward{frame.origin.x, frame.origin.y, 0.0};
  return glm::normalize(toward - frame.up * glm::dot(toward, frame.up));
}

// Stone towers whose size grows with distance so that each covers about the same part of the
// image (0.6 degrees wide, 1.7 tall: 12 by 35 pixels at 1080p and a 50 degree field of view),
// each of its own proportions (width and height factors) on a wider plinth under a wider cap, all of one albedo so that their differences in brightness come from the atmosphere alone:
// limestone, ~0.4 in the visible (the ECOSTRESS spectral library, Meerdink et al. 2019).
struct Landmark {
  Placement at;
  double width_factor, height_factor;
};
constexpr Landmark kLandmarks[] = {{{1e3, -12.0}, 1.0, 1.0},  {{2e3, 9.0}, 0.8, 1.25},
                                   {{5e3, -6.0}, 1.3, 0.8},   {{10e3, 4.0}, 0.9, 1.1},
                                   {{20e3, -2.0}, 1.2, 0.9},  {{40e3, 1.0}, 1.0, 1.2}};
constexpr glm::vec3 kLandmarkAlbedo{0.42f, 0.39f, 0.34f};

Mesh BuildLandmark(const Landmark& landmark, double planet_radius_m) {
  const Placement& at = landmark.at;
  glm::dvec2 xy = Horizontal(at);
  GroundFrame frame = GroundFrameAt(xy.x, xy.y, planet_radius_m);
  double width = (5.0 + 0.01 * at.distance_m) * landmark.width_factor;
  double height = (15.0 + 0.03 * at.distance_m) * landmark.height_factor;
  // Sunk into the ground by enough to cover the valley hills' slope (< 0.1) under its plinth.
  double plinth = 1.4 * width, sink = 1.0 + 0.1 * plinth;
  glm::dvec3 forward = AwayFromCamera(frame), right = glm::cross(forward, frame.up);
  Mesh mesh;
  mesh.name = "landmark_" + std::to_string(static_cast<int>(at.distance_m / 1e3)) + "km";
  const SurfaceLook stone{kLandmarkAlbedo, 1.0f};
  glm::dvec3 base = frame.origin - frame.up * sink;
  AppendBox(mesh, base, right, forward, {plinth, plinth, sink + 0.1 * height}, stone);
  AppendBox(mesh, base, right, forward, {width, width, sink + 0.92 * height}, stone);
  AppendBox(mesh, frame.origin + frame.up * (0.92 * height), right, forward,
            {1.2 * width, 1.2 * width, 0.08 * height}, stone);
  return mesh;
}

// A vertical glass pane facing the camera, its center at least at eye level, in an opaque frame
// of weathered aluminium (albedo 0.3) a fortieth of its width. Glass reflects ~4-8% and transmits
// most light; opacity 0.3 stands for a tinted, dirty pane.
struct Pane {
  Mesh glass, frame;
};

Pane BuildPane(const std::string& name, const Placement& at, double width_m, double height_m,
               double eye_altitude_m, double planet_radius_m) {
  glm::dvec2 xy = Horizontal(at);
  GroundFrame ground_frame = GroundFrameAt(xy.x, xy.y, planet_radius_m);
  double ground = TerrainHeightM(xy.x, xy.y);
  double center_height = std::max(eye_altitude_m, ground + height_m / 2.0 + 5.0);
  glm::dvec3 center = SurfacePoint(xy.x, xy.y, center_height, planet_radius_m);
  glm::dvec3 forward = AwayFromCamera(ground_frame), up = ground_frame.up;
  glm::dvec3 right = glm::cross(forward, up);
  Pane pane;
  pane.glass.name = name;
  pane.glass.transparent = true;
  AppendGrid(pane.glass, center, right, up, width_m, height_m, 16, 12, {{0.55f, 0.62f, 0.68f}, 0.3f});
  pane.frame.name = name + "_frame";
  const SurfaceLook metal{{0.3f, 0.3f, 0.3f}, 1.0f};
  double bar = width_m / 40.0, half_w = width_m / 2.0 + bar / 2.0, half_h = height_m / 2.0 + bar / 2.0;
  for (double side : {-1.0, 1.0}) {
    AppendBox(pane.frame, center + right * (side * half_w) - up * (half_h + bar / 2.0), right, forward,
              {bar, bar, height_m + 2.0 * bar}, metal);
    AppendBox(pane.frame, center + up * (side * half_h - bar / 2.0), right, forward, {width_m, bar, bar}, metal);
  }
  // The legs: from the frame's bottom down into the ground, deep enough for the hills' slope
  // (< 0.1) across the pane's width.
  double leg = center_height - height_m / 2.0 - ground + 1.0 + 0.1 * width_m;
  for (double side : {-1.0, 1.0})
    AppendBox(pane.frame, center + right * (side * half_w) - up * (half_h + bar / 2.0 + leg), right, forward,
              {bar, bar, leg}, metal);
  return pane;
}

// A hot-air balloon envelope: 60 m radius, 800 m above the ground 3 km away, 64 x 32 facets.
Mesh BuildBalloon(double planet_radius_m) {
  glm::dvec2 xy = Horizontal({3e3, -15.0});
  glm::dvec3 center = SurfacePoint(xy.x, xy.y, TerrainHeightM(xy.x, xy.y) + 800.0, planet_radius_m);
  Mesh mesh;
  mesh.name = "balloon";
  mesh.transparent = true;
  AppendUvSphere(mesh, center, 60.0, 64, 32, {{0.6f, 0.07f, 0.05f}, 0.6f});
  return mesh;
}

// 240 tetrahedra, 25-50 m across (3-7 pixels at 1080p), in a 500 m ball 700 m above the ground
// 8 km away, denser toward its centre: a small cloud or smoke plume, each particle faint (opacity
// 0.15) so that the overlapping ones build it up.
Mesh BuildParticleCloud(double planet_radius_m) {
  constexpr int kParticles = 240;
  constexpr double kBallRadiusM = 500.0;
  glm::dvec2 xy = Horizontal({8e3, 15.0});
  glm::dvec3 center = SurfacePoint(xy.x, xy.y, TerrainHeightM(xy.x, xy.y) + 700.0, planet_radius_m);
  Mesh mesh;
  mesh.name = "particle_cloud";
  mesh.transparent = true;
  uint32_t draw = 0;
  auto uniform = [&] { return UnitFromHash(Hash(draw++, 0x5eed)); };
  for (int i = 0; i < kParticles; ++i) {
    glm::dvec3 offset;
    do {  // rejection sampling of the ball from its bounding cube
      // One draw per statement: the order in which a call's arguments are evaluated is
      // unspecified (gcc and clang take them in opposite orders), and the cloud must be the same
      // from every compiler. z first, as the golden images hold it.
      double z = uniform(), y = uniform(), x = uniform();
      offset = glm::dvec3(x, y, z) * 2.0 - 1.0;
    } while (glm::dot(offset, offset) > 1.0);
    offset *= glm::length(offset);  // the density falls from the centre as distance^-1.5
    // Shoemake's uniform random rotation ("Uniform random rotations", Graphics Gems III).
    double u1 = uniform(), u2 = 2 * std::numbers::pi * uniform(),
           u3 = 2 * std::numbers::pi * uniform();
    glm::dquat q(std::sqrt(u1) * std::cos(u3), std::sqrt(1 - u1) * std::sin(u2),
                 std::sqrt(1 - u1) * std::cos(u2), std::sqrt(u1) * std::sin(u3));
    AppendTetrahedron(mesh, center + offset * kBallRadiusM, 15.0 + 15.0 * uniform(),
                      glm::mat3_cast(q), {{0.9f, 0.9f, 0.9f}, 0.15f});
  }
  return mesh;
}

}  // namespace

Scene BuildDefaultScene(double planet_radius_m) {
  Scene scene;
  ApplyPresetView(scene, "noon", planet_radius_m);
  scene.terrain = true;
  for (const Landmark& landmark : kLandmarks) scene.meshes.push_back(BuildLandmark(landmark, planet_radius_m));
  // Each pane covers landmarks behind it: the 300 m one those at 5 and 20 km, the 1.5 km one the
  // 2 km landmark, so landmarks seen through glass sit beside ones seen directly.
  double eye = scene.camera.position.z;
  Pane panes[] = {BuildPane("glass_300m", {300.0, -5.0}, 40.0, 30.0, eye, planet_radius_m),
                  BuildPane("glass_1500m", {1500.0, 8.0}, 200.0, 120.0, eye, planet_radius_m)};
  for (Pane& pane : panes) {
    scene.meshes.push_back(std::move(pane.frame));
    scene.meshes.push_back(std::move(pane.glass));
  }
  scene.meshes.push_back(BuildBalloon(planet_radius_m));
  scene.meshes.push_back(BuildParticleCloud(planet_radius_m));
  return scene;
}

}  // namespace aerial
