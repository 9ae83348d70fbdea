#include "aerial/precompute/spectral_precompute.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
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

// A table's RGBA texels as float32 (alpha unused but for transmittance's 1).
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

// sum.rgb += m * group.rgb, texel by texel; with `weights`, group.rgb is first multiplied by them.
void AddConverted(std::vector<float>& sum, const std::vector<float>& group, const Matrix3& m,
                  const Spectrum& weights = {1.0, 1.0, 1.0}) {
  for (size_t i = 0; i + 3 < group.size(); i += 4) {
    Spectrum value = {group[i] * weights[0], group[i + 1] * weights[1], group[i + 2] * weights[2]};
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
    for (size_t i = 0; i < result.tables.size(); ++i) {
      std::vector<float> texels = AsFloats(downloaded.tables[i]);
      if (result.tables[i].name == std::string("transmittance")) {
        // Optical depth to sunlight-weighted transmittance E * exp(-tau), converted.
        for (size_t t = 0; t + 3 < texels.size(); t += 4)
          for (int c = 0; c < 3; ++c) texels[t + c] = std::exp(-texels[t + c]);
        AddConverted(sums[i], texels, to_srgb, group_atmosphere.solar_irradiance);
      } else {
        AddConverted(sums[i], texels, to_srgb);
      }
    }
  }

  const Spectrum sun = ShaderAtmosphere(tables.atmosphere(), tables.options()).solar_irradiance;
  for (size_t i = 0; i < result.tables.size(); ++i) {
    CachedTable& table = result.tables[i];
    std::vector<float>& sum = sums[i];
    if (table.name == std::string("transmittance")) {
      // Back to an optical depth per channel; a channel whose sunlight is all gone (or whose
      // converted value the sRGB matrix's negative lobes took below 0) keeps a finite depth.
      for (size_t t = 0; t + 3 < sum.size(); t += 4) {
        for (int c = 0; c < 3; ++c)
          sum[t + c] = float(-std::log(std::clamp(sum[t + c] / sun[c], 1e-30, 1.0)));
        sum[t + 3] = 1.0f;
      }
    }
    table.texels = ToBytes(sum, table.format);
  }
  tables.Upload(result);
  if (progress) progress->Advance("spectral to linear sRGB");
  return times;
}

}  // namespace aerial
