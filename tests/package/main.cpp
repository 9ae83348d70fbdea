// The installed library end to end, through its public API only (include/aerial/): an atmosphere
// file loaded and validated, small 4D tables precomputed on a device of aerial's (lavapipe here),
// and the tables' zenith transmittance from the ground checked against this client's own
// quadrature of the atmosphere's optical depth; and a shared library of the client's that links
// aerial as well (position-independent code). examples/embed/ is the client with its own device.
//   package_client ATMOSPHERE.toml CACHE_DIR
#include <cmath>
#include <cstdio>
#include <exception>

#include <aerial/aerial.h>

extern "C" double PluginPlanetRadiusM();  // plugin.cpp, a shared library that links aerial too

namespace {

// exp(-optical depth) straight up from the ground: Rayleigh and Mie extinction and ozone
// absorption, each its cross-section times the integral of its density profile (midpoint rule,
// 10 m steps: the exponential scale heights are 1.2 km and more, so the rule's error is ~1e-6).
aerial::Spectrum ZenithTransmittance(const aerial::AtmosphereParameters& a) {
  const double thickness = a.top_radius_m - a.bottom_radius_m, step = 10.0;
  double rayleigh = 0.0, mie = 0.0, ozone = 0.0;
  for (double h = 0.5 * step; h < thickness; h += step) {
    rayleigh += a.rayleigh_density.Density(h) * step;
    mie += a.mie_density.Density(h) * step;
    ozone += a.absorption_density.Density(h) * step;
  }
  aerial::Spectrum t;
  for (int c = 0; c < 3; ++c)
    t[c] = std::exp(-(a.rayleigh_scattering[c] * rayleigh + a.mie_extinction[c] * mie +
                      a.absorption_extinction[c] * ozone));
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: package_client ATMOSPHERE.toml CACHE_DIR\n");
    return 2;
  }
  try {
    std::printf("aerial %s (%d.%d.%d)\n", AERIAL_VERSION, AERIAL_VERSION_MAJOR, AERIAL_VERSION_MINOR,
                AERIAL_VERSION_PATCH);
    aerial::AtmosphereParameters atmosphere = aerial::LoadAtmosphereFile(argv[1]);
    aerial::Device device;
    int passes = 0;
    aerial::Tables tables = aerial::Tables::LoadOrPrecompute(
        device, atmosphere, aerial::PrecomputeOptions::Small(),
        {.cache_dir = argv[2], .progress = [&](int, int, std::string_view) { ++passes; }});
    std::printf("tables %s (%d precompute passes reported)\n",
                tables.from_cache() ? "read from the cache" : "precomputed", passes);
    aerial::ProbeQuery query{aerial::ToRayParameters({.sun_zenith_deg = 30.0}, atmosphere)};
    aerial::ProbeResult probed = aerial::Probe(tables, {&query, 1})[0];
    aerial::Spectrum expected = ZenithTransmittance(atmosphere);
    // The transmittance table is within 0.11% of a double-precision reference on grazing rays
    // (docs/accuracy.md); 0.5% leaves room for the small tables' coarser r axis.
    bool ok = tables.from_cache() || passes > 0;
    for (int c = 0; c < 3; ++c) {
      double error = std::abs(probed.transmittance[c] / expected[c] - 1.0);
      std::printf("zenith transmittance, channel %d: tables %.6f, quadrature %.6f (%.3f%%)\n", c,
                  probed.transmittance[c], expected[c], 100.0 * error);
      ok = ok && error < 5e-3;
    }
    double plugin_radius = PluginPlanetRadiusM();
    std::printf("planet radius through the shared library: %.0f m\n", plugin_radius);
    ok = ok && plugin_radius == aerial::AtmosphereParameters::Earth().bottom_radius_m;
    // As in every test here, a validation message (with AERIAL_VALIDATION=1) is a failure.
    int messages = aerial::Device::ValidationMessageCount();
    std::printf("validation messages: %d\n", messages);
    return ok && messages == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "package_client: %s\n", e.what());
    return 1;
  }
}
