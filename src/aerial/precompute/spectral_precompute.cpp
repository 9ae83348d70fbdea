#include "aerial/precompute/spectral_precompute.h"

#include <Imath/half.h>

#include <algorithm>
#include <cstring>

#include "aerial/core/progress.h"
#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/precompute/precomputer.h"
#include "aerial/spectrum/spectral_atmosphere.h"

namespace aerial {
namespace {

using spectrum::Matrix3;
using spectrum::SpectralAtmosphere;
using spectrum::SpectralSampling;

// A float32 table's RGBA texels (the groups' tables are all float32).
std::vector<float> AsFloats(const CachedTable& table) {
  std::vector<float> texels(table.texels.size() / sizeof(float));
  std::memcpy(texels.data(), table.texels.data(), table.texels.size());
  return texels;
}

std::vector<std::byte> ToBytes(const std::vector<float>& rgba, TexelFormat format) {
  if (format == TexelFormat::kRgba32f) {
    std::vector<std::byte> bytes(rgba.size() * sizeof(float));
    std::memcpy(bytes.data(), rgba.data(), bytes.size());
    return bytes;
  }
  std::vector<Imath::half> halves(rgba.begin(), rgba.end());  // round to nearest even
  std::vector<std::byte> bytes(halves.size() * sizeof(Imath::half));
  std::memcpy(bytes.data(), halves.data(), bytes.size());
  return bytes;
}

// sum.rgb += m * group.rgb, texel by texel.
void AddConverted(std::vector<float>& sum, const std::vector<float>& group, const Matrix3& m) {
  for (size_t i = 0; i + 3 < group.size(); i += 4) {
    Spectrum value = {group[i], group[i + 1], group[i + 2]};
    Spectrum colour = spectrum::Multiply(m, value);
    for (int c = 0; c < 3; ++c) sum[i + c] += float(colour[c]);
  }
}

}  // namespace

AtmosphereParameters ShaderAtmosphere(const AtmosphereParameters& atmosphere, const PrecomputeOptions& options) {
  if (options.colour == ColourMode::kRgb) return atmosphere;
  return spectrum::LinearSrgbAtmosphere(SpectralAtmosphere(atmosphere), atmosphere,
                                        SpectralSampling(options.spectral_wavelengths));
}

int SpectralGroupCount(const PrecomputeOptions& options) { return options.spectral_wavelengths / 3; }

PrecomputeOptions SpectralGroupOptions(const PrecomputeOptions& options) {
  PrecomputeOptions group = options;
  group.colour = ColourMode::kRgb;
  group.precision = TablePrecision::kFloat32;  // rounded once, after the sum
  return group;
}

std::vector<vk::PassTime> PrecomputeSpectral(AtmosphereTables& tables, Progress* progress) {
  const SpectralSampling sampling(tables.options().spectral_wavelengths);
  const SpectralAtmosphere spectral(tables.atmosphere());
  const PrecomputeOptions group_options = SpectralGroupOptions(tables.options());
  // The final tables' layout; their contents are replaced below.
  TableCache result = tables.Download();
  std::vector<std::vector<float>> sums;
  for (const CachedTable& table : result.tables)
    sums.emplace_back(size_t(table.width) * table.height * table.depth * 4, 0.0f);

  std::vector<vk::PassTime> times;
  for (int g = 0; g < sampling.groups(); ++g) {
    AtmosphereParameters group_atmosphere = spectral.At(sampling.Group(g));
    AtmosphereTables group(tables.context(), group_atmosphere, group_options);
    for (vk::PassTime& t : PrecomputeRadiance(group, progress)) {
      t.pass = "[" + std::to_string(g + 1) + "/" + std::to_string(sampling.groups()) + "] " + t.pass;
      times.push_back(t);
    }
    const Matrix3 to_srgb = sampling.GroupToLinearSrgb(g);
    TableCache downloaded = group.Download();
    for (size_t i = 0; i < result.tables.size(); ++i)
      if (result.tables[i].name != std::string("transmittance"))
        AddConverted(sums[i], AsFloats(downloaded.tables[i]), to_srgb);
  }

  for (size_t i = 0; i < result.tables.size(); ++i) {
    CachedTable& table = result.tables[i];
    // Light whose colour lies outside sRGB's gamut (the Mie table's reddened sunlight near the
    // horizon, with blue down to -2e-3 where Rayleigh's is 5e-2) has negative channels. The sum
    // of the tables would cancel them, but the render-time reads blend exponentially and integrate
    // in log space, which need values >= 0: they are clamped to 0 (docs/colour.md).
    for (float& v : sums[i]) v = std::max(v, 0.0f);
    table.texels = ToBytes(sums[i], table.format);
  }
  tables.Upload(result);
  // Transmittance from the linear sRGB coefficients (additive along a ray, as the lookups that
  // divide two table values need), replacing the uploaded placeholder.
  times.push_back(ComputeTransmittance(tables));
  if (progress) progress->Advance("spectral to linear sRGB");
  return times;
}

}  // namespace aerial
