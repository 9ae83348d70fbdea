#pragma once
// What the renderer draws: meshes, one camera and the sun, in one world frame.
//
// World frame. A local east-north-up frame on the ground at the scene origin: x east, y north,
// z up, in meters. The planet is a sphere of radius R (the atmosphere's bottom_radius_m) centered
// at (0, 0, -R), so the ground at the origin is z = 0 and it falls away as z = sqrt(R^2 - d^2) - R
// (about -d^2 / 2R) at horizontal distance d. "Altitude" is |p - center| - R, the height above that
// sphere (the sea-level ground), not above the terrain mesh.
//
// Angles are in degrees. Azimuths are compass bearings measured in the horizontal plane of the
// origin: 0 = north (+y), 90 = east (+x), clockwise seen from above. Zenith angles are measured
// from +z. The sun is at infinity, so one direction serves every point of the scene; at 100 km
// from the origin the local vertical tilts by 100 km / R = 0.9 degrees from +z, which the
// atmosphere model accounts for when it works from r and mu_s at each point.
//
// Meshes. Positions are world positions (float: a 100 km scene keeps ~8 mm resolution), normals
// are unit length and triangles wind counter-clockwise seen from the side the normals point to.
// Albedo is linear RGB reflectance in [0, 1]. Opaque meshes have opacity 1 at every vertex;
// transparent ones (glass, a balloon, particles; opacity in (0, 1], below 1 in the built-in scene)
// must be blended after the opaque pass, each fragment attenuated and in-scattered by the air
// between it and the camera like an opaque one.
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace aerial {

struct Vertex {
  glm::vec3 position;  // world frame, m
  glm::vec3 normal;    // unit length
  glm::vec3 albedo;    // linear RGB in [0, 1]
  float opacity;       // 1 for opaque meshes; in (0, 1] for transparent ones
};

struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;  // triangle list, 3 per triangle
  bool transparent = false;
  // Opaque meshes are drawn with back faces culled unless they are double-sided (an open
  // surface seen from both sides). Transparent meshes are always drawn two-sided.
  bool double_sided = false;
};

// A pinhole camera. yaw_deg is the compass azimuth of the view direction, pitch_deg its elevation
// above the horizontal plane of the world frame (+90 looks straight up). There is no roll: the
// image's right edge stays horizontal. near_m is the near clipping plane; there is no far plane
// (see ProjectionMatrix in camera.h). jitter_px moves the image plane by a fraction of a pixel of
// the rendered frame, as engines jitter frames they average for antialiasing: the pixel whose
// centre is c shows what the unjittered frame shows at c + jitter_px (x right, y down).
struct Camera {
  glm::dvec3 position{0, 0, 2};
  double yaw_deg = 0, pitch_deg = 0, vertical_fov_deg = 60, near_m = 0.5;
  glm::dvec2 jitter_px{0, 0};
  bool operator==(const Camera&) const = default;
};

struct Sun {
  double zenith_deg = 30, azimuth_deg = 180;
  // Unit vector toward the sun: (sin z sin a, sin z cos a, cos z) for zenith z and azimuth a.
  glm::dvec3 Direction() const;
  bool operator==(const Sun&) const = default;
};

struct Scene {
  std::vector<Mesh> meshes;
  // The built-in procedural terrain (terrain.h) is part of the scene. It is not one of the meshes:
  // the renderer draws it with a level of detail that follows the camera (src/aerial/terrain/).
  bool terrain = false;
  Camera camera;
  Sun sun;
  std::string name;
};

// The built-in scene (default_scene.cpp): the procedural terrain with mountains 5-80 km away, stone
// towers named "landmark_<d>km" at d = 1, 2, 5, 10, 20 and 40 km, glass panes in opaque frames
// ("glass_<d>m" and "glass_<d>m_frame"), a balloon and a particle cloud; camera and sun from the
// "noon" preset (below).
Scene BuildDefaultScene(double planet_radius_m);

// Named views of the built-in scene: where the camera stands and looks, and where the sun is.
//   noon           sun 20 deg from the zenith in the south-southeast, camera 30 m above the
//                  valley floor looking north up the corridor of landmarks, pitched up 4 deg.
//   afternoon      the same view, sun at 55 deg in the southwest.
//   sunset         sun at 91 deg (just set) in the west; the camera looks east, away from it,
//                  where the Earth's shadow rises above the horizon under the pink Belt of Venus.
//   twilight       sun at 96 deg (civil twilight ends), camera looking west into the afterglow
//                  above the mountains' silhouettes.
//   high-altitude  camera 30 km up, above 98% of the air, looking north at the horizon (pitched
//                  down by the horizon's dip, acos(R / (R + h)) = 5.6 deg), sun at 50 deg.
//   evening        the noon view, sun low (11 deg above the horizon) in the west-northwest,
//                  behind the western ridges: their shadows cross the valley floor 0.5-1 km
//                  ahead and the corridor's foot, the landmarks' shadows point east (the sun's
//                  shadow map).
// PresetNames() lists them in this order.
std::vector<std::string> PresetNames();

// The built-in scene (BuildDefaultScene) seen from the named preset; scene.name is the preset's.
// An unknown name throws Error("preset name", name, "one of: noon, afternoon, ...").
Scene BuildPreset(const std::string& name, double planet_radius_m);

// Sets scene.camera, scene.sun and scene.name to the named preset's and leaves the meshes alone.
// Throws like BuildPreset.
void ApplyPresetView(Scene& scene, const std::string& name, double planet_radius_m);

// Scene files: a preset, changes to its camera and sun, glTF meshes (the keys: scene/scene_file.h).
// Reads a scene file; a missing or unreadable file throws an Error naming the path. The scene's
// name is the file's stem.
Scene LoadSceneFile(const std::filesystem::path& path, double planet_radius_m);

}  // namespace aerial
