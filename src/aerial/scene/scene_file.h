#pragma once
// Scene files: a preset plus changes to its camera and sun and extra glTF meshes, in TOML
// (examples/scenes/*.toml). Every key is optional:
//
//   preset = "noon"                  # the base scene (aerial/scene.h); default "noon"
//   built_in = true                  # the built-in terrain and models; false: only the meshes
//                                    # below, on the bare planet (the preset's camera and sun stay)
//   [camera]
//   position_m = [0.0, 0.0, 30.0]    # world frame of scene.h, m
//   yaw_deg = 0.0                    # compass azimuth of the view: 0 north, 90 east
//   pitch_deg = 4.0                  # above the horizontal, [-90, 90]
//   fov_deg = 50.0                   # vertical field of view, (1, 170)
//   near_m = 0.5                     # near plane, [0.001, 1000]
//   [sun]
//   zenith_deg = 20.0                # [0, 180]; above 90 the sun has set
//   azimuth_deg = 160.0              # compass, like yaw_deg
//   # or, instead of the two angles, the sun of a date and a place (sun_date_keys.h):
//   # date = 2003-10-17, time = 12:30:30, time_zone = "America/Denver" (or "-07:00"),
//   # latitude_deg = 39.74, longitude_deg = -105.18
//   [[mesh]]                         # any number of these
//   gltf = "cube.gltf"               # .gltf or .glb, relative to this file
//   position_m = [0.0, 800.0, 0.0]   # where the model's origin goes; [x, y] puts it on the ground
//   scale = 1.0                      # > 0, uniform
//   yaw_deg = 0.0                    # turns the model's front (-y after gltf_loader.h's axis
//                                    # change) clockwise seen from above, like a compass
//   transparent = false              # blend it; default: opacity < 1 or a BLEND glTF material
//   opacity = 1.0                    # (0, 1], multiplies the materials' alpha; < 1 needs
//                                    # transparent (not false)
//
// Camera altitude (above the planet's sphere) must lie in [-500, 100000] m, positions must be
// finite, and a placed mesh (position, scale and the model's own size) within 1000 km of the
// origin (scene_limits.h). Unknown keys, wrong types and out-of-range values throw aerial::Error
// naming the dotted key ("mesh[0].scale", "camera.fov_deg"), the value and the allowed range at
// "file:line:column"; a glTF that fails to load is reported at its mesh's gltf key.
#include <filesystem>
#include <string>
#include <string_view>

#include "aerial/core/memory_budget.h"
#include "aerial/scene.h"

namespace aerial {

// Parses TOML text; where names the source in messages, and glTF paths resolve against base_dir.
// Each glTF model loads within budget (gltf_loader.h).
Scene ParseSceneToml(std::string_view text, const std::string& where,
                     const std::filesystem::path& base_dir, double planet_radius_m,
                     const MemoryBudget& budget = MakeMemoryBudget(std::nullopt, UINT64_MAX));

// LoadSceneFile (aerial/scene.h) with the glTF models' memory budget.
Scene LoadSceneFile(const std::filesystem::path& path, double planet_radius_m, const MemoryBudget& budget);

}  // namespace aerial
