#pragma once
// What to precompute besides the atmosphere itself: table variant, precision, resolutions,
// scattering orders and the integration sample counts. Together with the atmosphere's hash they
// key the table cache.
#include <cstdint>
#include <string>

namespace aerial {

enum class LutVariant { k4D, k3D };
enum class TablePrecision { kFloat32, kFloat16 };
// What the tables' three channels hold: radiance at the atmosphere's three wavelengths (rgb, as
// Bruneton 2008), or linear sRGB converted with the CIE 1931 observer from a precompute at
// spectral_wavelengths wavelengths over 395-700 nm (spectral, Bruneton 2017's "precomputed
// luminance"; docs/colour.md).
enum class ColourMode { kRgb, kSpectral };

std::string ToString(LutVariant variant);         // "4d" / "3d"
LutVariant ParseLutVariant(const std::string& text, const std::string& field);  // throws Error
std::string ToString(TablePrecision precision);   // "float32" / "float16"
TablePrecision ParseTablePrecision(const std::string& text, const std::string& field);  // throws Error
std::string ToString(ColourMode colour);          // "rgb" / "spectral"
ColourMode ParseColourMode(const std::string& text, const std::string& field);  // throws Error

struct TableResolution {
  int transmittance_mu = 256;
  int transmittance_r = 64;
  int irradiance_mu_s = 64;
  // 32 rows: with 16 the sky irradiance 50 km up, interpolated across ~7 km of altitude per row,
  // was 13% off (measured with aerial_bench_sky); with 32 it is 3%.
  int irradiance_r = 32;
  int scattering_r = 32;
  int scattering_mu = 128;  // even: half for rays that hit the ground, half for the others
  // 36 on the arctangent mapping of mappings.glsl: the texels the low sun and twilight need,
  // within the memory budget (1.25x Bruneton 2017's 32, the multiple density table below
  // included). Fewer nu slices for more mu_s texels doubles the daylight error (docs/accuracy.md,
  // "Spending nu on mu_s instead", "38 mu_s texels instead of 40").
  int scattering_mu_s = 36;
  // 9 slices, in 16-bit floats (PrecomputeOptions::precision). An odd count puts a slice on
  // nu = 0, where the Earth's shadow changes fastest for a low sun (mappings.glsl,
  // GetNuFromUnitRange): that brings the low-sun sky within its 3% target, which 8 slices in
  // float32 miss, in less memory (docs/accuracy.md, "Nine nu slices in half floats").
  int scattering_nu = 9;    // 1 in the 3D variant
  // The scattering density of orders >= 2 (J_ms), which render-time marches integrate along a
  // segment instead of subtracting two table values (sky_lookup.glsl, GetSkyInscatterToPoint).
  // It is a convolution of the light field with the phase functions, smooth in r and mu, so a
  // coarse grid holds it there. It takes the density tables' own texels on every axis: resampled
  // to fewer, the radiance to a point with a low sun leaves its target (docs/accuracy.md, "J_ms
  // on the density tables' mu_s and nu texels", "... r texels"; 56 mu texels left the sky's
  // colour there 0.0015 off in u'v' instead of 0.0012, docs/colour.md).
  int multiple_density_r = 32;
  int multiple_density_mu = 64;  // even, split at the horizon like the scattering mu axis
  int multiple_density_mu_s = 36;
  int multiple_density_nu = 9;   // 1 in the 3D variant
};

struct PrecomputeOptions {
  LutVariant variant = LutVariant::k4D;
  // The 4D Rayleigh table in 16-bit floats: the default's 9 nu slices fit the memory budget that
  // way (in float32 they would take 47.5 MB), and half floats cost at most 0.05 points of error
  // anywhere against float32 (docs/accuracy.md; Mie and J_ms stay float32). The 3D and the small tables:
  // float32.
  TablePrecision precision = TablePrecision::kFloat16;
  int orders = 4;
  // After the last order, add the orders beyond it as a geometric series per texel (the tables then
  // stand for the whole series); off: exactly orders 1..N. Needs orders >= 3.
  bool close_series = true;
  ColourMode colour = ColourMode::kRgb;  // an embedder's cost stays; every command defaults to spectral
  // Wavelengths of the spectral mode, a multiple of 6: each has its single scattering, every other
  // one its orders >= 2 (the others read theirs between them), in precomputes of three. 12 put the
  // colour of sky light within 1.5e-4 in u'v' of the CIE integral, with weights fitted to it
  // (spectrum/sky_light_conversion.h, docs/colour.md).
  int spectral_wavelengths = 12;
  TableResolution resolution;
  // Small()'s density grid: the scattering density of each order integrates the incident light over
  // (12 + 4) x 12 zenith x azimuth cells instead of (16 + 8) x 16 (quick tests and looks).
  bool coarse_directions = false;

  // The default tables of a variant (the 3D variant has one nu slice in every table).
  static PrecomputeOptions Default(LutVariant variant = LutVariant::k4D);
  // Small tables for quick tests; same shape, roughly 1/16 of the texels.
  static PrecomputeOptions Small(LutVariant variant = LutVariant::k4D);

  // Whether the last order is followed by the series' tail (close_series, and orders >= 3 so that
  // the last two orders are both multiple scattering).
  bool ClosesSeries() const { return close_series && orders >= 3; }

  // The scattering orders the tables stand for: 1..orders, or the whole series (INT_MAX, which is
  // ReferenceOptions::orders' default) when it is closed.
  int RepresentedOrders() const;

  // Sets the scattering tables' size (the four resolution fields); the precompute's per-order
  // density tables follow it (same r, mu_s and nu, half the mu). Validate() checks the result.
  void SetScatteringSize(int r, int mu, int mu_s, int nu);

  // Throws aerial::Error naming the field, value and allowed range; each table's texel count is
  // capped so that an rgb precompute ends within minutes on a CPU driver (a spectral one takes
  // about spectral_wavelengths / 5 times as long: docs/usage.md).
  void Validate() const;
  uint64_t Hash() const;
  std::string Describe() const;  // one line, for logs and the cache header
};

// Memory by what sizes it (the --transmittance-size, --irradiance-size, --scattering-size and
// --multiple-density-size options), in bytes: used for the tables themselves and for the precompute's scratch tables.
struct TableBytes {
  uint64_t transmittance = 0, irradiance = 0, scattering = 0, multiple_density = 0;
  uint64_t total() const { return transmittance + irradiance + scattering + multiple_density; }
};

// The memory AtmosphereTables allocates for these options, known before allocating it: the
// scattering part is the Rayleigh and Mie tables (and in 3D the multiple scattering one).
TableBytes TableMemory(const PrecomputeOptions& options);

// The memory of the intermediate tables Precompute allocates besides `tables`, known before it
// allocates them: for spectral tables, also the per-wavelength precomputes and their sums, which
// grow with spectral_wavelengths.
TableBytes PrecomputeScratchMemory(const PrecomputeOptions& options);

}  // namespace aerial
