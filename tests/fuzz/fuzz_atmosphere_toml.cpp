// The atmosphere config (--atmosphere FILE): TOML text through the same parser and validation.
#include "aerial/atmosphere/config.h"
#include "aerial/error.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    aerial::ParseAtmosphereToml(aerial::fuzz::AsText(data, size), "fuzz.toml");
  } catch (const aerial::Error&) {
  }
  return 0;
}
