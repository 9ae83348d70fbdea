#include "aerial/precompute/spectral_precompute.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "aerial/core/progress.h"
#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/precompute/precomputer.h"
#include "aerial/spectrum/higher_orders.h"
#include "aerial/spectrum/spectral_atmosphere.h"

namespace aerial {
namespace {

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

// One wavelength's values of a table (one channel of a group's RGBA texels).
std::vector<float> Channel(const std::vector<float>& rgba, int channel) {
  std::vector<float> values(rgba.size() / 4);
  for (size_t i = 0; i < values.size(); ++i) values[i] = rgba[4 * i + channel];
  return values;
}

// sum.rgb += colour * values, texel by texel.
void AddColour(std::vector<float>& sum, const std::vector<float>& values, const Spectrum& colour) {
  for (size_t i = 0; i < values.size(); ++i)
    for (int c = 0; c < 3; ++c) sum[4 * i + c] += float(colour[c] * values[i]);
}

// A wavelength's orders >= 2 from those of its stencil's wavelengths (higher_orders.h), given as
// their log response, log(value / sun) (-infinity where the value is 0): the weighted sum of those
// logs, or, where one is -infinity, the weighted sum of the responses themselves.
std::vector<float> HigherOrdersFrom(const spectrum::HigherOrderStencil& stencil,
                                    const std::vector<const std::vector<float>*>& log_responses, double sun) {
  std::vector<float> result(log_responses[0]->size());
  for (size_t i = 0; i < result.size(); ++i) {
    double log_response = 0.0;
    for (size_t j = 0; j < log_responses.size(); ++j) log_response += stencil.weights[j] * (*log_responses[j])[i];
    if (std::isfinite(log_response)) {
      result[i] = float(sun * std::exp(log_response));
      continue;
    }
    double response = 0.0;
    for (size_t j = 0; j < log_responses.size(); ++j) response += stencil.weights[j] * std::exp((*log_responses[j])[i]);
    result[i] = float(sun * response);
  }
  return result;
}

// values -> log(max(value, 0) / sun), in place.
void ToLogResponse(std::vector<float>& values, double sun) {
  for (float& v : values) v = std::log(std::max(v, 0.0f) / float(sun));
}

// A table's texel count (its RGBA floats / 4).
size_t TexelCount(const CachedTable& table) { return size_t(table.width) * table.height * table.depth; }

}  // namespace

AtmosphereParameters ShaderAtmosphere(const AtmosphereParameters& atmosphere, const PrecomputeOptions& options) {
  if (options.colour == ColourMode::kRgb) return atmosphere;
  return spectrum::LinearSrgbAtmosphere(SpectralAtmosphere(atmosphere), atmosphere,
                                        SpectralSampling::ForTables(options.spectral_wavelengths));
}

int SpectralGroupCount(const PrecomputeOptions& options) { return options.spectral_wavelengths / 3; }

int SpectralAllOrderGroupCount(const PrecomputeOptions& options) {
  return options.orders > 1 ? options.spectral_wavelengths / 6 : 0;
}

PrecomputeOptions SpectralGroupOptions(const PrecomputeOptions& options, bool all_orders) {
  PrecomputeOptions group = options;
  group.colour = ColourMode::kRgb;
  group.precision = TablePrecision::kFloat32;  // rounded once, after the sum
  if (!all_orders) group.orders = 1;
  return group;
}

TableBytes SpectralPrecomputeScratchMemory(const PrecomputeOptions& options) {
  const PrecomputeOptions group = SpectralGroupOptions(options, true);
  const TableBytes group_tables = TableMemory(group), group_scratch = PrecomputeScratchMemory(group);
  const TableBytes result = TableMemory(options);
  const uint64_t wavelengths_with_all_orders = 3 * uint64_t(SpectralAllOrderGroupCount(options));
  // The group's tables are float32 RGBA, 16 bytes a texel, so group_tables counts the texels too.
  auto part = [&](uint64_t TableBytes::*table, bool has_higher_orders) {
    const uint64_t rgba = group_tables.*table, texels = rgba / 16;
    return group_tables.*table + group_scratch.*table  // a group's device tables and scratch
           + 2 * rgba                                  // its read-backs: single scattering, all orders
           + 2 * rgba                                  // both as float vectors (AsFloats)
           + rgba                                      // the sums
           + 3 * texels * 4                            // one wavelength's channel (twice), a stencil's
           + (has_higher_orders ? wavelengths_with_all_orders * texels * 4 : 0)  // `higher`
           + 3 * result.*table;  // the final tables' read-back, their conversion, the upload's staging
  };
  // Each group also leaves the driver and the allocator holding memory the tables do not explain:
  // from 12 to 48 wavelengths over the small tables the peak grew 2.4 MiB a group more than they
  // do (lavapipe's pipelines, the heap's fragments), counted here at 4 MiB.
  constexpr uint64_t kBytesPerGroup = uint64_t{4} << 20;
  // The transmittance table is computed again from the linear sRGB coefficients, not summed.
  return {.transmittance = part(&TableBytes::transmittance, false),
          .irradiance = part(&TableBytes::irradiance, true),
          .scattering = part(&TableBytes::scattering, true) + SpectralGroupCount(options) * kBytesPerGroup,
          .multiple_density = part(&TableBytes::multiple_density, true)};
}

std::vector<vk::PassTime> PrecomputeSpectral(AtmosphereTables& tables, Progress* progress) {
  const PrecomputeOptions& options = tables.options();
  const SpectralSampling sampling = SpectralSampling::ForTables(options.spectral_wavelengths);
  const std::vector<double>& nm = sampling.wavelengths_nm();
  const int count = int(nm.size());
  const SpectralAtmosphere spectral(tables.atmosphere());
  const bool higher_orders = options.orders > 1;
  // The final tables' layout; their contents are replaced below.
  TableCache result = tables.Download();
  const size_t table_count = result.tables.size();
  auto skipped = [&](size_t table) { return result.tables[table].name == std::string("transmittance"); };
  std::vector<std::vector<float>> sums;
  for (const CachedTable& table : result.tables) sums.emplace_back(TexelCount(table) * 4, 0.0f);
  // higher[w][table]: what the orders >= 2 add at wavelength w, where it has all orders.
  std::vector<std::vector<std::vector<float>>> higher(count);

  std::vector<vk::PassTime> times;
  int group_index = 0;
  // Precomputes the tables at three wavelengths: single scattering, added to the sums, and if
  // all_orders, what the other orders add, kept in `higher`.
  auto run_group = [&](const std::array<int, 3>& indices, bool all_orders) {
    AtmosphereTables group(tables.context(), spectral.At({nm[indices[0]], nm[indices[1]], nm[indices[2]]}),
                           SpectralGroupOptions(options, all_orders));
    TableCache single;
    const std::string label = std::to_string(++group_index) + "/" + std::to_string(SpectralGroupCount(options));
    for (vk::PassTime& t : PrecomputeRadiance(group, progress, [&] { single = group.Download(); })) {
      t.pass = "[" + label + "] " + t.pass;
      times.push_back(t);
    }
    TableCache whole = group.Download();
    if (!all_orders) single = std::move(whole);
    for (size_t i = 0; i < table_count; ++i) {
      if (skipped(i)) continue;
      const std::vector<float> single_texels = AsFloats(single.tables[i]);
      const std::vector<float> whole_texels = all_orders ? AsFloats(whole.tables[i]) : std::vector<float>{};
      for (int k = 0; k < 3; ++k) {
        std::vector<float> values = Channel(single_texels, k);
        AddColour(sums[i], values, sampling.WavelengthToLinearSrgb(indices[k]));
        if (!all_orders) continue;
        const std::vector<float> all = Channel(whole_texels, k);
        for (size_t t = 0; t < values.size(); ++t) values[t] = all[t] - values[t];
        higher[indices[k]].resize(table_count);
        higher[indices[k]][i] = std::move(values);
      }
    }
  };
  // The wavelengths with all orders, then the others' single scattering, three at a time.
  std::vector<int> with_all, single_only;
  for (int w = 0; w < count; ++w) (higher_orders && spectrum::HasAllOrders(w) ? with_all : single_only).push_back(w);
  for (size_t g = 0; g < with_all.size(); g += 3) run_group({with_all[g], with_all[g + 1], with_all[g + 2]}, true);
  for (size_t g = 0; g < single_only.size(); g += 3)
    run_group({single_only[g], single_only[g + 1], single_only[g + 2]}, false);

  // The orders >= 2 at every wavelength: as computed, then read between those.
  if (higher_orders) {
    for (int w = 0; w < count; ++w)
      for (size_t i = 0; i < table_count; ++i) {
        if (skipped(i) || !spectrum::HasAllOrders(w)) continue;
        AddColour(sums[i], higher[w][i], sampling.WavelengthToLinearSrgb(w));
        ToLogResponse(higher[w][i], spectral.SolarIrradiance(nm[w]));
      }
    const std::vector<spectrum::HigherOrderStencil> stencils = spectrum::HigherOrderStencils(sampling, spectral);
    for (int w = 0; w < count; ++w)
      for (size_t i = 0; i < table_count; ++i) {
        if (skipped(i) || spectrum::HasAllOrders(w)) continue;
        std::vector<const std::vector<float>*> log_responses;
        for (int k : stencils[w].from) log_responses.push_back(&higher[k][i]);
        AddColour(sums[i], HigherOrdersFrom(stencils[w], log_responses, spectral.SolarIrradiance(nm[w])),
                  sampling.WavelengthToLinearSrgb(w));
      }
  }

  for (size_t i = 0; i < result.tables.size(); ++i) {
    CachedTable& table = result.tables[i];
    // Light whose colour lies outside sRGB's gamut (the Mie table's reddened sunlight near the
    // horizon, with blue down to -2e-3 where Rayleigh's is 5e-2) keeps its negative channel: the
    // render-time reads blend such values linearly (MixExponentially) and clamp sums by their
    // XYZ (ClampToLight).
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
