#pragma once
// Shared by the libFuzzer targets of this directory (one per input aerial reads from users; see
// tools/fuzz.sh). A target passes when aerial either accepts the input or rejects it with an
// aerial::Error: any other exception escapes to libFuzzer, which reports it as a crash, just as
// a sanitizer report or a signal is one. That is the promise of docs/usage.md: bad input gets a named
// error, never a crash.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace aerial::fuzz {

// The input as text (TOML, JSON).
inline std::string_view AsText(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// For loaders that take a path: writes the input to a file of this process in /dev/shm (memory,
// so that millions of runs do not wear a disk) with the given extension, and returns its path.
std::filesystem::path WriteInputFile(const uint8_t* data, size_t size, std::string_view extension);

// Earth's radius, for loaders that check altitudes against the planet.
inline constexpr double kPlanetRadiusM = 6360e3;

}  // namespace aerial::fuzz
