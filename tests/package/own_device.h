#pragma once
// The client's own Vulkan instance and device, made as a renderer that embeds aerial would make
// them (with the extensions and features aerial asks for), and aerial run on them: the tables
// precomputed, a frame recorded into the client's command buffer and submitted by the client.
#include <filesystem>

#include "aerial/atmosphere/parameters.h"

// True when the frame the client submitted equals, pixel for pixel, the frame aerial submits
// itself on the same device, and no validation message was seen (with AERIAL_VALIDATION=1 the
// client's instance has the validation layers and counts their messages).
bool RunOnOwnDevice(const aerial::AtmosphereParameters& atmosphere, const std::filesystem::path& cache_dir);
