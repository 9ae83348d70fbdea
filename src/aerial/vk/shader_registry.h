#pragma once
// The SPIR-V modules compiled from shaders/ at build time (cmake/Shaders.cmake embeds them).
#include <cstdint>
#include <span>
#include <string>

namespace aerial::shaders {
// name: the path under shaders/, e.g. "precompute/transmittance.comp". Empty when unknown.
std::span<const uint32_t> Find(const std::string& name);
// A hash of every embedded module: it changes whenever any shader does, so caches of computed
// tables can tell which build made them.
uint64_t Fingerprint();
}  // namespace aerial::shaders
