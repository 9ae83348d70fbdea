#pragma once
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
//                  shadow map, src/aerial/render/shadow_map.h).
#include <string>
#include <vector>

#include "aerial/scene.h"

namespace aerial {

// Sets scene.camera, scene.sun and scene.name to the named preset's and leaves the meshes alone.
// Throws like BuildPreset.
void ApplyPresetView(Scene& scene, const std::string& name, double planet_radius_m);

}  // namespace aerial
