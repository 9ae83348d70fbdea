// The viewer's camera path (--camera-path FILE): TOML keyframes.
#include "aerial/error.h"
#include "aerial/viewer/camera_path.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    aerial::viewer::CameraPath::Parse(aerial::fuzz::AsText(data, size), "fuzz.toml",
                                      aerial::fuzz::kPlanetRadiusM);
  } catch (const aerial::Error&) {
  }
  return 0;
}
