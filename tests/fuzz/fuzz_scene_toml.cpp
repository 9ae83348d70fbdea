// The scene file (--scene FILE): TOML text; its glTF paths resolve against examples/scenes, so
// the seeds' meshes load and a mutated path reaches the glTF loader's file checks.
#include "aerial/error.h"
#include "aerial/scene/scene_file.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    aerial::ParseSceneToml(aerial::fuzz::AsText(data, size), "fuzz.toml",
                           AERIAL_SOURCE_DIR "/examples/scenes", aerial::fuzz::kPlanetRadiusM);
  } catch (const aerial::Error&) {
  }
  return 0;
}
