#include "aerial/scene/scene_file.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "aerial/core/toml_reader.h"
#include "aerial/error.h"
#include "aerial/scene/gltf_loader.h"
#include "aerial/scene.h"
#include "aerial/scene/scene_limits.h"
#include "aerial/scene/sun_date_keys.h"
#include "aerial/scene/terrain.h"

namespace aerial {
namespace {

// An optional number key of a [camera] or [sun] table: the member it sets, its unit and its range
// check (scene_limits.h).
template <typename T>
struct NumberKey {
  const char* key;
  double T::*member;
  const char* unit;
  void (*check)(double value, const std::string& field, const std::string& where);
};

template <typename T>
void ReadNumbers(TomlReader& r, const toml::table& t, const std::string& prefix, T& target,
                 std::initializer_list<NumberKey<T>> keys) {
  for (const NumberKey<T>& k : keys) {
    IfPresent(t, k.key, [&](const toml::node& n) {
      std::string field = TomlReader::Join(prefix, k.key);
      target.*k.member = r.Number(n, field, k.unit);
      k.check(target.*k.member, field, r.At(n));
    });
  }
}

void ReadCamera(TomlReader& r, const toml::table& t, double planet_radius_m, Camera& camera) {
  r.RejectUnknownKeys(t, "camera", {"position_m", "yaw_deg", "pitch_deg", "fov_deg", "near_m"});
  IfPresent(t, "position_m", [&](const toml::node& n) {
    std::vector<double> p = r.Numbers(n, "camera.position_m", 3, 3, "m");
    camera.position = {p[0], p[1], p[2]};
    CheckCameraPosition(camera.position, planet_radius_m, "camera.position_m", r.At(n));
  });
  ReadNumbers<Camera>(r, t, "camera", camera,
                      {{"yaw_deg", &Camera::yaw_deg, "degrees", CheckAzimuthDeg},
                       {"pitch_deg", &Camera::pitch_deg, "degrees", CheckPitchDeg},
                       {"fov_deg", &Camera::vertical_fov_deg, "degrees", CheckFovDeg},
                       {"near_m", &Camera::near_m, "m", CheckNearM}});
}

void ReadSun(TomlReader& r, const toml::table& t, Sun& sun) {
  r.RejectUnknownKeys(t, "sun",
                      {"zenith_deg", "azimuth_deg", "date", "time", "time_zone", "latitude_deg", "longitude_deg"});
  ReadNumbers<Sun>(r, t, "sun", sun,
                   {{"zenith_deg", &Sun::zenith_deg, "degrees", CheckZenithDeg},
                    {"azimuth_deg", &Sun::azimuth_deg, "degrees", CheckAzimuthDeg}});
  ReadSunDate(r, t, sun);
}

// Scale, then turn about z by yaw clockwise seen from above (a model's +y goes to compass
// azimuth yaw), then move the origin to anchor.
struct Placement {
  Placement(const glm::dvec3& anchor, double scale, double yaw_deg) : anchor(anchor), scale(scale) {
    double yaw = yaw_deg * std::numbers::pi / 180.0, c = std::cos(yaw), s = std::sin(yaw);
    turn = glm::dmat3(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0);  // columns: images of x, y, z
  }
  glm::dvec3 Position(const glm::vec3& model) const { return anchor + turn * (scale * glm::dvec3(model)); }
  // The largest distance from the scene origin of a placed vertex, in double.
  double Farthest(const Mesh& mesh) const {
    double farthest = glm::length(anchor);
    for (const Vertex& v : mesh.vertices) farthest = std::max(farthest, glm::length(Position(v.position)));
    return farthest;
  }
  void Apply(Mesh& mesh) const {
    for (Vertex& v : mesh.vertices) {
      v.position = glm::vec3(Position(v.position));
      v.normal = glm::vec3(turn * glm::dvec3(v.normal));
    }
  }

  glm::dvec3 anchor;
  double scale;
  glm::dmat3 turn;
};

// terrain: whether [x, y] positions stand on the built-in terrain or on the bare planet.
Mesh ReadMesh(TomlReader& r, const toml::node& node, const std::string& field,
              const std::filesystem::path& base_dir, double planet_radius_m, bool terrain,
              const MemoryBudget& budget) {
  auto key = [&](std::string_view k) { return TomlReader::Join(field, k); };
  const toml::table& t = r.Table(node, field);
  r.RejectUnknownKeys(t, field,
                      {"gltf", "position_m", "scale", "yaw_deg", "transparent", "opacity"});
  const toml::node* gltf = t.get("gltf");
  if (!gltf) {
    throw Error(key("gltf"), "", "the path of a .gltf or .glb file", r.At(node));
  }
  std::filesystem::path path = base_dir / r.String(*gltf, key("gltf"));

  glm::dvec3 anchor(0.0);
  double scale = 1.0, yaw_deg = 0.0, opacity = 1.0;
  std::optional<bool> transparent;
  IfPresent(t, "position_m", [&](const toml::node& n) {
    std::string name = key("position_m");
    std::vector<double> p = r.Numbers(n, name, 2, 3, "m");
    for (size_t i = 0; i < p.size(); ++i)
      if (!std::isfinite(p[i]))
        r.Fail(*n.as_array()->get(i), TomlReader::Index(name, i), "a finite number (m)");
    anchor = p.size() == 3 ? glm::dvec3(p[0], p[1], p[2])
                           : SurfacePoint(p[0], p[1], terrain ? TerrainHeightM(p[0], p[1]) : 0.0, planet_radius_m);
  });
  IfPresent(t, "scale", [&](const toml::node& n) {
    scale = r.Number(n, key("scale"), "");
    if (!(scale > 0.0 && std::isfinite(scale))) r.Fail(n, key("scale"), "> 0 and finite");
  });
  IfPresent(t, "yaw_deg", [&](const toml::node& n) {
    yaw_deg = r.Number(n, key("yaw_deg"), "degrees");
    CheckAzimuthDeg(yaw_deg, key("yaw_deg"), r.At(n));
  });
  IfPresent(t, "transparent",
            [&](const toml::node& n) { transparent = r.Bool(n, key("transparent")); });
  IfPresent(t, "opacity", [&](const toml::node& n) {
    std::string name = key("opacity");
    opacity = r.Number(n, name, "");
    if (!(opacity > 0.0 && opacity <= 1.0)) r.Fail(n, name, "(0, 1]");
    if (opacity < 1.0 && transparent == false)
      r.Fail(n, name, "1 when " + key("transparent") + " = false");
  });

  Mesh mesh;
  try {
    mesh = LoadGltfMesh(path, path.stem().string(), budget);
  } catch (const Error& e) {
    // The loader's own field ("meshes[0].primitives[1].mode") and value go into the message.
    std::string problem = e.value() == path.string() ? e.allowed()
                                                     : "a loadable glTF; its " + e.field() + " = " +
                                                           e.value() + ", expected " + e.allowed();
    throw Error(key("gltf"), path.string(), problem, r.At(*gltf));
  }
  mesh.transparent = transparent.value_or(mesh.transparent || opacity < 1.0);
  for (Vertex& v : mesh.vertices)
    v.opacity = mesh.transparent ? static_cast<float>(v.opacity * opacity) : 1.0f;
  // Checked before the positions become floats, which would overflow to inf (scale = 1e300).
  // The message blames the anchor when it alone is too far, else the scale, else the model.
  Placement placement(anchor, scale, yaw_deg);
  const char* culprit = glm::length(anchor) > kMaxSceneDistanceM ? "position_m"
                        : t.get("scale")                         ? "scale"
                                                                 : "gltf";
  const toml::node& culprit_node = *t.get(culprit);
  CheckPlacedDistance(placement.Farthest(mesh), key(culprit), r.NodeText(culprit_node), r.At(culprit_node));
  placement.Apply(mesh);
  return mesh;
}

}  // namespace

Scene ParseSceneToml(std::string_view text, const std::string& where,
                     const std::filesystem::path& base_dir, double planet_radius_m,
                     const MemoryBudget& budget) {
  // Floats shown in their shortest form ("50"), as the range checks show them.
  TomlReader r(where, FormatNumber);
  toml::table root = r.Parse(text);
  r.RejectUnknownKeys(root, "", {"preset", "built_in", "camera", "sun", "mesh"});
  bool built_in = true;
  IfPresent(root, "built_in", [&](const toml::node& n) { built_in = r.Bool(n, "built_in"); });
  // Everything is read and checked on the preset's view and the extra meshes first, and the
  // built-in scene is built only once the file is known to be valid.
  Scene view;
  std::string preset = "noon";
  IfPresent(root, "preset", [&](const toml::node& n) {
    preset = r.String(n, "preset");
    try {
      ApplyPresetView(view, preset, planet_radius_m);
    } catch (const Error& e) {
      r.Fail(n, "preset", e.allowed());
    }
  });
  if (!root.get("preset")) ApplyPresetView(view, preset, planet_radius_m);
  IfPresent(root, "camera", [&](const toml::node& n) {
    ReadCamera(r, r.Table(n, "camera"), planet_radius_m, view.camera);
  });
  IfPresent(root, "sun", [&](const toml::node& n) { ReadSun(r, r.Table(n, "sun"), view.sun); });
  IfPresent(root, "mesh", [&](const toml::node& n) {
    const toml::array* meshes = n.as_array();
    if (!meshes) r.Fail(n, "mesh", "an array of tables ([[mesh]])");
    // One budget for all the models: each loads beside those loaded before it, which stay.
    uint64_t held = 0;
    for (size_t i = 0; i < meshes->size(); ++i) {
      MemoryBudget with_models =
          held == 0 ? budget : budget.Holding({{"scene file", where, "the glTF models before mesh[" + std::to_string(i) + "]", held}});
      view.meshes.push_back(ReadMesh(r, *meshes->get(i), TomlReader::Index("mesh", i), base_dir, planet_radius_m,
                                     built_in, with_models));
      held += HeldMeshBytes(view.meshes.back());
    }
  });

  Scene scene = built_in ? BuildDefaultScene(planet_radius_m) : Scene{};
  scene.camera = view.camera;
  scene.sun = view.sun;
  scene.name = view.name;
  for (Mesh& mesh : view.meshes) scene.meshes.push_back(std::move(mesh));
  return scene;
}

Scene LoadSceneFile(const std::filesystem::path& path, double planet_radius_m) {
  return LoadSceneFile(path, planet_radius_m, MakeMemoryBudget(std::nullopt, UINT64_MAX));
}

Scene LoadSceneFile(const std::filesystem::path& path, double planet_radius_m, const MemoryBudget& budget) {
  Scene scene = ParseSceneToml(ReadTomlFile(path, "scene file"), path.string(), path.parent_path(),
                               planet_radius_m, budget);
  scene.name = path.stem().string();
  return scene;
}

}  // namespace aerial
