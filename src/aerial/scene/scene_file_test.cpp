#include "aerial/scene/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "aerial/error.h"
#include "aerial/scene/terrain.h"

#ifndef AERIAL_SOURCE_DIR
#define AERIAL_SOURCE_DIR "."
#endif

namespace aerial {
namespace {

constexpr double kR = 6360e3;
const std::filesystem::path kExamples =
    std::filesystem::path(AERIAL_SOURCE_DIR) / "examples/scenes";

// Built once: the terrain takes most of a second.
const Scene& Builtin() {
  static const Scene scene = BuildDefaultScene(kR);
  return scene;
}

Scene Parse(const std::string& text) { return ParseSceneToml(text, "test.toml", kExamples, kR); }

// Parsing must fail with an Error naming field, located at test.toml:line.
void ExpectError(const std::string& text, const std::string& field, int line) {
  try {
    Parse(text);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), field) << text << "\n" << e.what();
    EXPECT_EQ(e.where().rfind("test.toml:" + std::to_string(line) + ":", 0), 0u) << text << "\n"
                                                                                 << e.what();
    EXPECT_FALSE(e.allowed().empty()) << e.what();
  }
}

TEST(SceneFile, DefaultExampleIsTheBuiltInScene) {
  Scene file = LoadSceneFile(kExamples / "default.toml", kR);
  const Scene& built = Builtin();
  EXPECT_EQ(file.name, "default");
  EXPECT_EQ(file.meshes.size(), built.meshes.size());
  // Exact: the file spells out the preset's values, and TOML decimals like 4.0 are exact.
  EXPECT_EQ(file.camera.position, built.camera.position);
  EXPECT_EQ(file.camera.yaw_deg, built.camera.yaw_deg);
  EXPECT_EQ(file.camera.pitch_deg, built.camera.pitch_deg);
  EXPECT_EQ(file.camera.vertical_fov_deg, built.camera.vertical_fov_deg);
  EXPECT_EQ(file.camera.near_m, built.camera.near_m);
  EXPECT_EQ(file.sun.zenith_deg, built.sun.zenith_deg);
  EXPECT_EQ(file.sun.azimuth_deg, built.sun.azimuth_deg);
}

TEST(SceneFile, GltfExamplePlacesItsMeshes) {
  Scene scene = LoadSceneFile(kExamples / "with-gltf.toml", kR);
  const Scene& base = Builtin();
  ASSERT_EQ(scene.meshes.size(), base.meshes.size() + 2);
  EXPECT_EQ(scene.camera.pitch_deg, 3.0);
  EXPECT_EQ(scene.sun.zenith_deg, 55.0);  // from the afternoon preset

  const Mesh& on_ground = scene.meshes[scene.meshes.size() - 2];
  EXPECT_EQ(on_ground.name, "cube");
  EXPECT_FALSE(on_ground.transparent);
  EXPECT_EQ(on_ground.indices.size(), 36u);
  // position_m = [x, y]: the cube's base (its origin) is on the terrain there. The cube is 10 m,
  // scaled by 3; float rounding of ~500 m coordinates is well under 1 mm.
  double bottom = HUGE_VAL, top = -HUGE_VAL;
  for (const Vertex& v : on_ground.vertices) {
    bottom = std::min<double>(bottom, v.position.z);
    top = std::max<double>(top, v.position.z);
    EXPECT_EQ(v.opacity, 1.0f);
  }
  glm::dvec3 ground = SurfacePoint(-180.0, 450.0, TerrainHeightM(-180.0, 450.0), kR);
  EXPECT_NEAR(bottom, ground.z, 1e-3);
  EXPECT_NEAR(top - bottom, 30.0, 1e-3);

  const Mesh& floating = scene.meshes.back();
  EXPECT_TRUE(floating.transparent);
  for (const Vertex& v : floating.vertices) EXPECT_FLOAT_EQ(v.opacity, 0.4f);
}

// built_in = false: only the file's meshes on the bare planet, no terrain; [x, y] stands a model
// on the planet's sphere (z = SurfacePoint at height 0, about -d^2 / 2R), not on the terrain.
TEST(SceneFile, WithoutTheBuiltInSceneOnlyTheFilesMeshesStandOnTheBarePlanet) {
  Scene scene = Parse("preset = \"sunset\"\nbuilt_in = false\n[[mesh]]\ngltf = \"cube.gltf\"\n"
                      "position_m = [3000.0, 4000.0]\n");
  EXPECT_FALSE(scene.terrain);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.sun, BuildPreset("sunset", kR).sun);  // the preset's view stays
  double bottom = HUGE_VAL;
  for (const Vertex& v : scene.meshes[0].vertices) bottom = std::min<double>(bottom, v.position.z);
  EXPECT_NEAR(bottom, SurfacePoint(3000.0, 4000.0, 0.0, kR).z, 1e-3);
  EXPECT_LT(bottom, -1.9);  // 5 km from the origin the sphere is 2 m down
  ExpectError("built_in = 1", "built_in", 1);
}

TEST(SceneFile, EmptyFileIsTheNoonPreset) {
  Scene scene = Parse("");
  EXPECT_EQ(scene.name, "noon");
  EXPECT_EQ(scene.sun.zenith_deg, Builtin().sun.zenith_deg);
}

TEST(SceneFile, EachInvalidFieldIsNamedWithItsLine) {
  ExpectError("preset = \"dusk\"", "preset", 1);
  ExpectError("preset = 3", "preset", 1);
  ExpectError("[camera]\nfov_deg = 170", "camera.fov_deg", 2);
  ExpectError("[camera]\nfov_deg = 1", "camera.fov_deg", 2);
  ExpectError("[camera]\nnear_m = 0", "camera.near_m", 2);
  ExpectError("[camera]\nnear_m = inf", "camera.near_m", 2);
  ExpectError("[camera]\nnear_m = 1e30", "camera.near_m", 2);  // finite in float, and clips everything
  ExpectError("[camera]\nnear_m = 1e-300", "camera.near_m", 2);  // 0 in float
  ExpectError("[camera]\npitch_deg = 90.5", "camera.pitch_deg", 2);
  ExpectError("[camera]\nyaw_deg = nan", "camera.yaw_deg", 2);
  ExpectError("[camera]\nyaw_deg = \"north\"", "camera.yaw_deg", 2);
  ExpectError("[camera]\n\nposition_m = [0, 0, 100001]", "camera.position_m", 3);
  ExpectError("[camera]\nposition_m = [0, 0, -501]", "camera.position_m", 2);
  ExpectError("[camera]\nposition_m = [0, 0]", "camera.position_m", 2);
  ExpectError("[camera]\nposition_m = [0, nan, 2]", "camera.position_m[1]", 2);
  ExpectError("[sun]\nzenith_deg = -0.1", "sun.zenith_deg", 2);
  ExpectError("[sun]\nzenith_deg = 180.5", "sun.zenith_deg", 2);
  ExpectError("[sun]\nazimuth_deg = inf", "sun.azimuth_deg", 2);
  ExpectError("camera = 3", "camera", 1);
  ExpectError("mesh = 3", "mesh", 1);
  const std::string cube = "[[mesh]]\ngltf = \"cube.gltf\"\n";
  ExpectError(cube + "scale = 0", "mesh[0].scale", 3);
  ExpectError(cube + "scale = -2", "mesh[0].scale", 3);
  ExpectError(cube + "scale = 1e300", "mesh[0].scale", 3);  // inf as float positions
  ExpectError(cube + "scale = 2e5", "mesh[0].scale", 3);    // a 10 m cube reaching 1000 km out
  ExpectError(cube + "position_m = [0, 0, 1e30]", "mesh[0].position_m", 3);
  ExpectError(cube + "opacity = 0", "mesh[0].opacity", 3);
  ExpectError(cube + "opacity = 1.5", "mesh[0].opacity", 3);
  ExpectError(cube + "transparent = false\nopacity = 0.5", "mesh[0].opacity", 4);
  ExpectError(cube + "transparent = 1", "mesh[0].transparent", 3);
  ExpectError(cube + "position_m = [1, 2, 3, 4]", "mesh[0].position_m", 3);
  ExpectError(cube + "position_m = [1, inf]", "mesh[0].position_m[1]", 3);
  ExpectError(cube + "yaw_deg = nan", "mesh[0].yaw_deg", 3);
  // Finite, but degrees x pi would overflow (every pixel NaN) or the mesh would vanish.
  ExpectError("[camera]\nyaw_deg = 5.8e307", "camera.yaw_deg", 2);
  ExpectError("[sun]\nazimuth_deg = -1e308", "sun.azimuth_deg", 2);
  ExpectError(cube + "yaw_deg = 1e308", "mesh[0].yaw_deg", 3);
  ExpectError("[[mesh]]\ngltf = \"" + std::string(AERIAL_SOURCE_DIR) +
                  "/tests/data/hostile/translation_1e308.gltf\"",
              "mesh[0].gltf", 2);
  ExpectError(cube + "[[mesh]]\nscale = 2", "mesh[1].gltf", 3);
  ExpectError("[[mesh]]\ngltf = \"missing.glb\"", "mesh[0].gltf", 2);
}

// Values that are finite as doubles but not as the floats the GPU receives are named with their
// value.
TEST(SceneFile, ValuesBeyondFloatAreNamedWithTheirValue) {
  for (auto [text, message] : {std::pair{"[camera]\nnear_m = 1e30", "camera.near_m = 1e+30 is invalid"},
                               std::pair{"[[mesh]]\ngltf = \"cube.gltf\"\nscale = 1e300",
                                         "mesh[0].scale = 1e+300 (places a vertex"}}) {
    try {
      Parse(text);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

TEST(SceneFile, MissingGltfNamesThePath) {
  try {
    Parse("[[mesh]]\ngltf = \"missing.glb\"");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.value(), (kExamples / "missing.glb").string());
    EXPECT_NE(std::string(e.what()).find("missing.glb"), std::string::npos);
  }
}

TEST(SceneFile, UnknownKeysAreRejected) {
  ExpectError("presets = \"noon\"", "presets", 1);
  ExpectError("[camera]\nfov = 50", "camera.fov", 2);
  ExpectError("[sun]\nelevation_deg = 10", "sun.elevation_deg", 2);
  ExpectError("[[mesh]]\ngltf = \"cube.gltf\"\nrotation = 3", "mesh[0].rotation", 3);
  try {
    Parse("[camera]\nfov = 50");
  } catch (const Error& e) {
    EXPECT_NE(e.allowed().find("fov_deg"), std::string::npos) << "lists the known keys";
  }
}

TEST(SceneFile, SyntaxErrorsHaveALine) { ExpectError("[camera\nfov_deg = 50", "TOML syntax", 1); }

// One budget for every model of a scene: each loads beside those loaded before it. The budget
// here is the least that one model needs to load (found by bisection, in bytes); ten copies of it
// must not pass. Before, each model was checked alone, so ten copies of a 137 MiB model passed
// --max-memory-mib 400 and peaked at 1.45 GB.
TEST(SceneFile, ModelsShareOneMemoryBudget) {
  auto scene = [](int copies) {
    std::string text = "built_in = false\n";
    for (int i = 0; i < copies; ++i) text += "[[mesh]]\ngltf = \"cube.gltf\"\nposition_m = [0.0, 0.0]\n";
    return text;
  };
  auto loads = [&](int copies, uint64_t bytes) {
    try {
      ParseSceneToml(scene(copies), "test.toml", kExamples, kR, MemoryBudget{bytes, "test"});
      return true;
    } catch (const Error&) {
      return false;
    }
  };
  uint64_t low = 1, high = uint64_t{1} << 30;  // loads(1, high), !loads(1, low)
  ASSERT_TRUE(loads(1, high));
  while (high - low > 1) {
    uint64_t middle = low + (high - low) / 2;
    (loads(1, middle) ? high : low) = middle;
  }
  EXPECT_TRUE(loads(1, high));
  try {
    ParseSceneToml(scene(10), "test.toml", kExamples, kR, MemoryBudget{high, "test"});
    FAIL() << "ten models loaded within the budget of one";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "mesh[1].gltf") << e.what();
    EXPECT_NE(e.allowed().find("the glTF models before mesh[1]"), std::string::npos) << e.what();
  }
}

TEST(SceneFile, MissingFileNamesThePath) {
  try {
    LoadSceneFile(kExamples / "no-such-scene.toml", kR);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(e.value().find("no-such-scene.toml"), std::string::npos);
  }
}

}  // namespace
}  // namespace aerial
