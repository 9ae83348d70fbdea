#include "aerial/table_options.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

#include "aerial/error.h"
#include "aerial/precompute/sample_counts.h"
#include "aerial/precompute/table_layout.h"

namespace aerial {

std::string ToString(LutVariant variant) { return variant == LutVariant::k4D ? "4d" : "3d"; }

LutVariant ParseLutVariant(const std::string& text, const std::string& field) {
  if (text == "4d") return LutVariant::k4D;
  if (text == "3d") return LutVariant::k3D;
  throw Error(field, text, "4d or 3d");
}

std::string ToString(TablePrecision precision) {
  return precision == TablePrecision::kFloat32 ? "float32" : "float16";
}

TablePrecision ParseTablePrecision(const std::string& text, const std::string& field) {
  if (text == "float32") return TablePrecision::kFloat32;
  if (text == "float16") return TablePrecision::kFloat16;
  throw Error(field, text, "float16 or float32");
}

std::string ToString(ColourMode colour) { return colour == ColourMode::kRgb ? "rgb" : "spectral"; }

ColourMode ParseColourMode(const std::string& text, const std::string& field) {
  if (text == "rgb") return ColourMode::kRgb;
  if (text == "spectral") return ColourMode::kSpectral;
  throw Error(field, text, "rgb or spectral");
}

PrecomputeOptions PrecomputeOptions::Default(LutVariant variant) {
  PrecomputeOptions options;
  options.variant = variant;
  if (variant == LutVariant::k3D) {
    options.resolution.scattering_nu = 1;
    options.resolution.multiple_density_nu = 1;
    options.precision = TablePrecision::kFloat32;
  }
  return options;
}

PrecomputeOptions PrecomputeOptions::Small(LutVariant variant) {
  PrecomputeOptions options;
  options.variant = variant;
  options.precision = TablePrecision::kFloat32;
  options.resolution = {.transmittance_mu = 128, .transmittance_r = 32, .irradiance_mu_s = 32,
                        .irradiance_r = 8, .scattering_r = 16, .scattering_mu = 64,
                        .scattering_mu_s = 16, .scattering_nu = variant == LutVariant::k4D ? 8 : 1,
                        .multiple_density_r = 8, .multiple_density_mu = 16,
                        .multiple_density_mu_s = 8,
                        .multiple_density_nu = variant == LutVariant::k4D ? 4 : 1};
  options.coarse_directions = true;
  return options;
}

void PrecomputeOptions::SetScatteringSize(int r, int mu, int mu_s, int nu) {
  resolution.scattering_r = r;
  resolution.scattering_mu = mu;
  resolution.scattering_mu_s = mu_s;
  resolution.scattering_nu = nu;
}

SampleCounts SampleCountsOf(const PrecomputeOptions& options) {
  const TableResolution& r = options.resolution;
  SampleCounts s;
  s.density_r = r.scattering_r;
  s.density_mu = std::max(4, (r.scattering_mu / 4) * 2);  // half of mu, even
  s.density_mu_s = r.scattering_mu_s;
  s.density_nu = r.scattering_nu;
  if (options.coarse_directions) {
    s.density_theta_up = 12;
    s.density_theta_down = 4;
    s.density_phi = 12;
  }
  return s;
}

namespace {
void CheckRange(const std::string& field, int value, int low, int high) {
  if (value < low || value > high)
    throw Error(field, std::to_string(value), "an integer in [" + std::to_string(low) + ", " +
                                                  std::to_string(high) + "]");
}
// A mu axis is split at the horizon into two equal halves, so its size must be even.
void CheckMuAxis(const std::string& field, int value) {
  CheckRange(field, value, 4, 1024);
  if (value % 2 != 0)
    throw Error(field, std::to_string(value), "an even number (split at the horizon)");
}

// The tables' texel counts are capped so that the slowest allowed rgb precompute (every table at
// its cap, 16 orders) ends within a few minutes on lavapipe with 2 cores: it took 188 s there,
// with another job on one of the cores (docs/usage.md, "Memory, disks and the device"). The
// per-axis ranges alone allowed 4096x4096 transmittance and irradiance tables, which ran for over
// 5 minutes. A spectral precompute repeats the work per three wavelengths, so its time also grows
// with spectral_wavelengths, which these caps do not bound.
constexpr int64_t kMaxTransmittanceTexels = int64_t(1) << 20;  // 1024x1024: 6 s
constexpr int64_t kMaxIrradianceTexels = int64_t(1) << 14;     // 256x64: 1.4 s per order
// 32x128x128x8, 3.2 times the default: single scattering 26 s, then 8.7 s per order.
constexpr int64_t kMaxScatteringTexels = int64_t(1) << 22;

void CheckTexels(const std::string& field, std::initializer_list<int> axes, int64_t cap) {
  int64_t texels = 1;
  std::string size;
  for (int axis : axes) {
    texels *= axis;
    if (!size.empty()) size += 'x';
    size += std::to_string(axis);
  }
  if (texels > cap)
    throw Error(field, size + " = " + std::to_string(texels) + " texels",
                "at most " + std::to_string(cap) + " texels, so that an rgb precompute ends within minutes");
}

// A nu axis has exactly one slice in the 3D variant, 2 to 64 in the 4D one.
void CheckNuAxis(const std::string& field, int value, LutVariant variant) {
  if (variant == LutVariant::k3D)
    CheckRange(field + " (3d variant)", value, 1, 1);
  else
    CheckRange(field, value, 2, 64);
}

}  // namespace

void PrecomputeOptions::Validate() const {
  CheckRange("orders", orders, 1, 16);
  // 48 is one wavelength per 10 nm of the solar and ozone data; each group of 3 is a precompute,
  // and every other wavelength has its own higher orders, in groups of 3 too.
  if (colour == ColourMode::kSpectral && (spectral_wavelengths % 6 != 0 || spectral_wavelengths < 6 ||
                                          spectral_wavelengths > 48))
    throw Error("wavelengths", std::to_string(spectral_wavelengths), "a multiple of 6 in [6, 48]");
  const TableResolution& r = resolution;
  CheckRange("transmittance width (mu)", r.transmittance_mu, 4, 4096);
  CheckRange("transmittance height (r)", r.transmittance_r, 4, 4096);
  CheckRange("irradiance width (mu_s)", r.irradiance_mu_s, 4, 4096);
  CheckRange("irradiance height (r)", r.irradiance_r, 2, 4096);
  CheckRange("scattering r", r.scattering_r, 2, 512);
  CheckMuAxis("scattering mu", r.scattering_mu);
  CheckRange("scattering mu_s", r.scattering_mu_s, 2, 512);
  CheckNuAxis("scattering nu", r.scattering_nu, variant);
  // The 3D image packs nu and mu_s along x: its width is bounded by maxImageDimension3D (>= 2048).
  CheckRange("scattering nu * mu_s", r.scattering_nu * r.scattering_mu_s, 2, 2048);
  CheckRange("multiple density r", r.multiple_density_r, 2, 512);
  CheckMuAxis("multiple density mu", r.multiple_density_mu);
  CheckRange("multiple density mu_s", r.multiple_density_mu_s, 2, 512);
  CheckNuAxis("multiple density nu", r.multiple_density_nu, variant);
  CheckTexels("TableResolution::transmittance_mu/r", {r.transmittance_mu, r.transmittance_r},
              kMaxTransmittanceTexels);
  CheckTexels("TableResolution::irradiance_mu_s/r", {r.irradiance_mu_s, r.irradiance_r}, kMaxIrradianceTexels);
  CheckTexels("TableResolution::scattering_r/mu/mu_s/nu",
              {r.scattering_r, r.scattering_mu, r.scattering_mu_s, r.scattering_nu}, kMaxScatteringTexels);
  CheckTexels("multiple density size",
              {r.multiple_density_r, r.multiple_density_mu, r.multiple_density_mu_s, r.multiple_density_nu},
              kMaxScatteringTexels);
}

int PrecomputeOptions::RepresentedOrders() const {
  return ClosesSeries() ? std::numeric_limits<int>::max() : orders;
}

uint64_t PrecomputeOptions::Hash() const {
  // The sample counts are derived, but hashed as when they were options, so that the key of a
  // cached table did not change when they stopped being options.
  const SampleCounts samples = SampleCountsOf(*this);
  const int values[] = {kTableLayout, int(variant), int(precision), orders, int(close_series),
                        int(colour), colour == ColourMode::kSpectral ? spectral_wavelengths : 0,
                        resolution.transmittance_mu, resolution.transmittance_r,
                        resolution.irradiance_mu_s, resolution.irradiance_r, resolution.scattering_r,
                        resolution.scattering_mu, resolution.scattering_mu_s, resolution.scattering_nu,
                        resolution.multiple_density_r, resolution.multiple_density_mu,
                        resolution.multiple_density_mu_s, resolution.multiple_density_nu,
                        samples.transmittance_steps, samples.ray_steps, samples.multiple_scattering_steps, samples.irradiance_zenith,
                        samples.irradiance_azimuth, samples.density_theta_up,
                        samples.density_theta_down, samples.density_phi, samples.density_r,
                        samples.density_mu, samples.density_mu_s, samples.density_nu};
  uint64_t h = 1469598103934665603ull;
  for (int v : values) {
    unsigned char bytes[sizeof(int)];
    std::memcpy(bytes, &v, sizeof(int));
    for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
  }
  return h;
}

std::string PrecomputeOptions::Describe() const {
  const TableResolution& r = resolution;
  std::string colour_text =
      colour == ColourMode::kRgb ? "rgb" : "spectral " + std::to_string(spectral_wavelengths) + " wavelengths";
  return ToString(variant) + " " + ToString(precision) + ", " + colour_text +
         ", " + std::to_string(orders) + " orders" + (ClosesSeries() ? " + series tail" : "") +
         ", transmittance " +
         std::to_string(r.transmittance_mu) + "x" + std::to_string(r.transmittance_r) +
         ", irradiance " + std::to_string(r.irradiance_mu_s) + "x" + std::to_string(r.irradiance_r) +
         ", scattering R" + std::to_string(r.scattering_r) + " MU" + std::to_string(r.scattering_mu) +
         " MU_S" + std::to_string(r.scattering_mu_s) + " NU" + std::to_string(r.scattering_nu) +
         ", multiple density R" + std::to_string(r.multiple_density_r) + " MU" +
         std::to_string(r.multiple_density_mu) + " MU_S" + std::to_string(r.multiple_density_mu_s) +
         " NU" + std::to_string(r.multiple_density_nu);
}

}  // namespace aerial
