// The installed library end to end: an atmosphere file loaded and validated, small 4D tables
// precomputed on the Vulkan device (lavapipe here), and the tables' zenith transmittance from the
// ground checked against aerial's CPU reference in double precision; and a shared library of the
// client's that links aerial as well (position-independent code); then the same on the client's
// own Vulkan device, with a frame the client submits (own_device.h).
//   package_client ATMOSPHERE.toml CACHE_DIR
#include <cmath>
#include <cstdio>
#include <exception>

#include "aerial/atmosphere/config.h"
#include "aerial/core/error.h"
#include "aerial/precompute/table_store.h"
#include "aerial/probe/table_probe.h"
#include "aerial/reference/reference.h"
#include "aerial/vk/context.h"

#include "own_device.h"

extern "C" double PluginPlanetRadiusM();  // plugin.cpp, a shared library that links aerial too

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: package_client ATMOSPHERE.toml CACHE_DIR\n");
    return 2;
  }
  try {
    aerial::AtmosphereParameters atmosphere = aerial::LoadAtmosphereFile(argv[1]);
    aerial::vk::Context context;
    aerial::LoadedTables loaded =
        aerial::LoadOrPrecompute(context, atmosphere, aerial::PrecomputeOptions::Small(),
                                 {.cache_dir = argv[2], .quiet = true});
    aerial::RayParameters zenith = aerial::ToRayParameters({.sun_zenith_deg = 30.0}, atmosphere);
    aerial::ProbeQuery query{zenith};
    aerial::ProbeResult tables = aerial::ProbeTables(*loaded.tables, {&query, 1})[0];
    aerial::Spectrum expected = aerial::reference::Reference(atmosphere).Transmittance(
        zenith.r, zenith.mu, atmosphere.top_radius_m - zenith.r);
    // The transmittance table is within 0.11% of the reference on grazing rays (README); 0.5%
    // leaves room for the small tables' coarser r axis.
    bool ok = true;
    for (int c = 0; c < 3; ++c) {
      double error = std::abs(tables.transmittance[c] / expected[c] - 1.0);
      std::printf("zenith transmittance, channel %d: tables %.6f, reference %.6f (%.3f%%)\n", c,
                  tables.transmittance[c], expected[c], 100.0 * error);
      ok = ok && error < 5e-3;
    }
    double plugin_radius = PluginPlanetRadiusM();
    std::printf("planet radius through the shared library: %.0f m\n", plugin_radius);
    ok = ok && plugin_radius == aerial::AtmosphereParameters::Earth().bottom_radius_m;
    // As in every test here, a validation message (with AERIAL_VALIDATION=1) is a failure.
    int messages = aerial::vk::Context::ValidationMessageCount();
    std::printf("validation messages: %d\n", messages);
    ok = ok && messages == 0;
    return ok && RunOnOwnDevice(atmosphere, argv[2]) ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "package_client: %s\n", e.what());
    return 1;
  }
}
