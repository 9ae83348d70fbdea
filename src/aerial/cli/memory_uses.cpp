#include "aerial/cli/memory_uses.h"

#include <cstdio>

#include "aerial/core/format_number.h"


namespace aerial::cli {
namespace {

std::string Join(std::initializer_list<int> values, const char* separator) {
  std::string text;
  for (int v : values) text += (text.empty() ? "" : separator) + std::to_string(v);
  return text;
}

}  // namespace

std::vector<MemoryUse> TableMemoryUses(const PrecomputeOptions& options) {
  const TableResolution& r = options.resolution;
  TableBytes tables = TableMemory(options);
  TableBytes scratch = PrecomputeScratchMemory(options);
  const std::string what =
      options.colour == ColourMode::kSpectral
          ? "tables, precompute scratch (spectral, " + std::to_string(options.spectral_wavelengths) +
                " wavelengths) and cache copies"
          : "tables, precompute scratch and cache copies";
  return {{"--transmittance-size", Join({r.transmittance_mu, r.transmittance_r}, ","), what,
           3 * tables.transmittance + scratch.transmittance},
          {"--irradiance-size", Join({r.irradiance_mu_s, r.irradiance_r}, ","), what,
           3 * tables.irradiance + scratch.irradiance},
          {"--scattering-size", Join({r.scattering_r, r.scattering_mu, r.scattering_mu_s, r.scattering_nu}, ","),
           what, 3 * tables.scattering + scratch.scattering},
          {"--multiple-density-size",
           Join({r.multiple_density_r, r.multiple_density_mu, r.multiple_density_mu_s, r.multiple_density_nu}, ","),
           what, 3 * tables.multiple_density + scratch.multiple_density}};
}

std::vector<MemoryUse> FrameMemoryUses(const RendererOptions& render, int renderers) {
  FrameMemory frame = EstimateFrameMemory(render);
  std::string size = Join({render.width, render.height}, "x");
  char scale[64] = "";
  if (render.render_scale != 1.0) std::snprintf(scale, sizeof scale, " at --render-scale %g", render.render_scale);
  std::vector<MemoryUse> uses = {
      {"--width/--height", size, std::string("render targets") + scale + ", read-back and encoded image",
       renderers * frame.targets + frame.readback},
      {"--froxels", Join({render.froxels.width, render.froxels.height, render.froxels.depth}, "x"),
       "froxel volume", renderers * frame.froxels}};
  if (frame.terrain > 0)
    uses.push_back({"--terrain", "lod", "terrain chunk slots and their selection", renderers * frame.terrain});
  if (render.shadows) uses.push_back({"--shadows", "on", "shadow map and sun visibility", renderers * frame.shadows});
  return uses;
}

constexpr uint64_t kBytesPerExportedVoxel = 320;

std::vector<MemoryUse> FroxelExportMemoryUses(const FroxelGrid& grid) {
  return {{"--froxels", Join({grid.width, grid.height, grid.depth}, "x"), "froxel export copies",
           uint64_t(grid.width) * grid.height * grid.depth * kBytesPerExportedVoxel}};
}

std::vector<MemoryUse> WorldGridMemoryUses(double voxel_m, uint64_t voxels) {
  return {{"--world-grid", FormatNumber(voxel_m), "world grid volume (" + std::to_string(voxels) + " voxels)",
           voxels * kBytesPerExportedVoxel}};
}

std::vector<MemoryUse> FrustumGridMemoryUses(const FroxelGrid& grid, uint64_t voxels) {
  return {{"--froxels", Join({grid.width, grid.height, grid.depth}, "x"),
           "frustum grid volume (" + std::to_string(voxels) + " voxels)", voxels * kBytesPerExportedVoxel}};
}

std::vector<MemoryUse> SceneMemoryUses(const Scene& scene, const std::string& source, int renderers) {
  uint64_t bytes = 0;
  for (const Mesh& mesh : scene.meshes)
    bytes += uint64_t(mesh.vertices.capacity()) * sizeof(Vertex) + uint64_t(mesh.indices.capacity()) * sizeof(uint32_t);
  return {{"--scene", source, "meshes: the scene's copy, GPU buffers and upload copies",
           bytes * (1 + 2 * uint64_t(renderers))}};
}

std::vector<MemoryUse> SwapchainMemoryUses(const RenderOptions& window) {
  constexpr uint64_t kImages = 4, kBytesPerPixel = 4;
  return {{"--width/--height", Join({window.width, window.height}, "x"), "swapchain images",
           kImages * kBytesPerPixel * uint64_t(window.width) * window.height}};
}

std::vector<MemoryUse> Combined(std::vector<MemoryUse> a, const std::vector<MemoryUse>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace aerial::cli
