#include "aerial/envmap/environment_map.h"

#include <OpenEXR/ImfEnvmap.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "aerial/error.h"
#include "aerial/shader_abi/camera_frame_block.h"
#include "aerial/view_geometry.h"
#include "aerial/vk/compute_pipeline.h"

namespace aerial {
namespace {

// OpenEXR's envmap frame (Y up) in the scene frame: X north, Y up, Z east.
glm::dvec3 SceneFromExr(const Imath::V3f& exr) { return glm::normalize(glm::dvec3(exr.z, exr.x, exr.y)); }

struct LatticeShape {
  int32_t rows, azimuths;
};
struct MapConstants {
  int32_t width, height, face_height, sun_disc, azimuths, rows_above, rows_below;
  float zenith_above, zenith_below;
};

// The lattice's azimuth nodes over [0, pi]: one every 32 texels of a lat-long map as wide, at
// least 64 (65 nodes 2.8 degrees apart up to 2048 texels). The phase-free inscatter is smooth in
// azimuth (the phases, which are not, are applied per texel): tests/envmap_test.cpp holds a map
// of 65 nodes to the probe's values within 0.5%.
int AzimuthNodes(int lat_long_width) { return std::clamp(lat_long_width / 32, 64, 512) + 1; }

// A cube map's lattice rows on each side of the horizon, evenly in zenith angle: two per texel
// of a face's side, at least 256 (a third of a degree).
int CubeRowsPerSide(int face_size) { return std::max(2 * face_size, 256); }

// Just off the horizon on either side, so that a row never straddles it.
constexpr double kHorizonMargin = 1e-4;

}  // namespace

std::array<int, 2> EnvironmentImageSize(const EnvironmentMapOptions& options) {
  if (options.layout == EnvironmentLayout::kLatLong) return {2 * options.size, options.size};
  return {options.size, 6 * options.size};
}

void LatLongDirections(int width, int height, std::span<glm::vec4> out) {
  std::vector<double> sin_azimuth(width), cos_azimuth(width);
  for (int x = 0; x < width; ++x) {
    const double azimuth = 2.0 * std::numbers::pi * (x + 0.5) / width - 0.5 * std::numbers::pi;
    sin_azimuth[x] = std::sin(azimuth);
    cos_azimuth[x] = std::cos(azimuth);
  }
  for (int y = 0; y < height; ++y) {
    const double zenith = std::numbers::pi * (y + 0.5) / height;
    const double sin_zenith = std::sin(zenith), cos_zenith = std::cos(zenith);
    for (int x = 0; x < width; ++x)
      out[size_t(y) * width + x] = glm::vec4(sin_zenith * sin_azimuth[x], sin_zenith * cos_azimuth[x], cos_zenith, 0.0);
  }
}

void CubeDirections(int face_size, std::span<glm::vec4> out) {
  const Imath::Box2i window(Imath::V2i(0, 0), Imath::V2i(face_size - 1, 6 * face_size - 1));
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < face_size; ++j) {
      for (int i = 0; i < face_size; ++i) {
        const Imf::CubeMapFace f = Imf::CubeMapFace(face);
        const Imath::V2f in_face{float(i), float(j)};
        const Imath::V2f pixel = Imf::CubeMap::pixelPosition(f, window, in_face);
        out[size_t(std::lround(pixel.y)) * face_size + size_t(std::lround(pixel.x))] =
            glm::vec4(glm::vec3(SceneFromExr(Imf::CubeMap::direction(f, window, in_face))), 0.0f);
      }
    }
  }
}

EnvironmentMap RenderEnvironmentMap(const AtmosphereTables& tables, const EnvironmentMapOptions& options) {
  const AtmosphereParameters& atmosphere = tables.atmosphere();
  ValidateViewAngles({.altitude_m = options.altitude_m, .sun_zenith_deg = options.sun.zenith_deg}, atmosphere);
  // Plain variables, not a structured binding: the dispatch's lambda captures them (clang 14).
  const std::array<int, 2> size = EnvironmentImageSize(options);
  const int width = size[0], height = size[1];
  CheckImageSize(width, height);
  const bool lat_long = options.layout == EnvironmentLayout::kLatLong;

  // The lattice's rows: the lat-long map's own, or evenly on each side of the horizon.
  MapConstants constants{width, height, lat_long ? height : options.size, options.sun_disc ? 1 : 0,
                         AzimuthNodes(lat_long ? width : 4 * options.size), 0, 0, 0.0f, 0.0f};
  std::vector<float> rows;
  if (lat_long) {
    for (int y = 0; y < height; ++y) rows.push_back(float(std::numbers::pi * (y + 0.5) / height));
  } else {
    const double r = atmosphere.bottom_radius_m + options.altitude_m;
    const double horizon = std::numbers::pi - std::asin(std::min(atmosphere.bottom_radius_m / r, 1.0));
    const double above = horizon - kHorizonMargin, below = horizon + kHorizonMargin;
    constants.rows_above = constants.rows_below = CubeRowsPerSide(options.size);
    constants.zenith_above = float(above);
    constants.zenith_below = float(below);
    for (int i = 0; i < constants.rows_above; ++i) rows.push_back(float(above * i / (constants.rows_above - 1)));
    for (int i = 0; i < constants.rows_below; ++i)
      rows.push_back(float(below + (std::numbers::pi - below) * i / (constants.rows_below - 1)));
  }
  const LatticeShape shape{int32_t(rows.size()), constants.azimuths};

  const vk::Context& context = tables.context();
  auto storage = [&](size_t bytes) {
    return vk::Buffer(context, {.size = bytes, .usage = ::vk::BufferUsageFlagBits::eStorageBuffer, .host_visible = true});
  };
  const size_t texels = size_t(width) * height;
  vk::Buffer direction_buffer = storage(texels * sizeof(glm::vec4));
  const std::span<glm::vec4> directions(reinterpret_cast<glm::vec4*>(direction_buffer.mapped()), texels);
  if (lat_long) {
    LatLongDirections(width, height, directions);
  } else {
    CubeDirections(options.size, directions);
  }
  vk::Buffer row_buffer = storage(rows.size() * sizeof(float));
  row_buffer.Write(std::as_bytes(std::span(rows)));
  vk::Buffer lattice_buffer = storage(rows.size() * size_t(shape.azimuths) * 3 * sizeof(glm::vec4));
  vk::Buffer radiance_buffer = storage(texels * sizeof(glm::vec4));
  vk::Buffer sun_buffer = storage(sizeof(glm::vec4));
  // The point on the planet's +z axis, its vertical the scene frame's: only the camera's position
  // and the sun reach the shaders (GetCameraRayParameters, GetSkyViewFrame).
  FrameCamera camera;
  camera.view_projection = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  camera.position_m = {0.0, 0.0, options.altitude_m};
  const glm::dvec3 sun = options.sun.Direction();
  camera.sun_direction = {sun.x, sun.y, sun.z};
  camera.width = uint32_t(width);
  camera.height = uint32_t(height);
  const FrameUniforms frame = MakeFrameUniforms(camera, atmosphere.bottom_radius_m, FroxelGrid{});
  vk::Buffer frame_buffer(context, {.size = sizeof(FrameUniforms),
                                    .usage = ::vk::BufferUsageFlagBits::eUniformBuffer,
                                    .host_visible = true});
  frame_buffer.Write(std::as_bytes(std::span(&frame, 1)));

  vk::ComputePipeline lattice(
      context, "envmap/envmap_lattice.comp",
      {{"AtmosphereBlock", vk::kUniform}, {"FrameBlock", vk::kUniform}, {"transmittance_texture", vk::kSampled},
       {"rayleigh_texture", vk::kSampled}, {"mie_texture", vk::kSampled}, {"multiple_texture", vk::kSampled},
       {"irradiance_texture", vk::kSampled}, {"Rows", vk::kStorageBuffer}, {"Lattice", vk::kStorageBuffer}},
      sizeof(LatticeShape));
  vk::ComputePipeline texels_pass(
      context, "envmap/envmap.comp",
      {{"AtmosphereBlock", vk::kUniform}, {"FrameBlock", vk::kUniform}, {"transmittance_texture", vk::kSampled},
       {"Directions", vk::kStorageBuffer}, {"Lattice", vk::kStorageBuffer}, {"Radiance", vk::kStorageBuffer},
       {"Sunlight", vk::kStorageBuffer}},
      sizeof(MapConstants));
  context.Submit([&](const auto& cmd) {
    const vk::UniformBufferSlot atmosphere_block{&tables.uniform_buffer()}, frame_block{&frame_buffer};
    lattice.Dispatch(cmd,
                     {atmosphere_block, frame_block, tables.Sampled(tables.transmittance()),
                      tables.Sampled(tables.rayleigh()), tables.Sampled(tables.mie()),
                      tables.Sampled(tables.multiple()), tables.Sampled(tables.irradiance()),
                      vk::StorageBufferSlot{&row_buffer}, vk::StorageBufferSlot{&lattice_buffer}},
                     {uint32_t(shape.azimuths), uint32_t(shape.rows), 1}, {64, 1, 1}, &shape);
    vk::FullBarrier(cmd);
    texels_pass.Dispatch(cmd,
                         {atmosphere_block, frame_block, tables.Sampled(tables.transmittance()),
                          vk::StorageBufferSlot{&direction_buffer}, vk::StorageBufferSlot{&lattice_buffer},
                          vk::StorageBufferSlot{&radiance_buffer}, vk::StorageBufferSlot{&sun_buffer}},
                         {uint32_t(width), uint32_t(height), 1}, {64, 1, 1}, &constants);
    vk::FullBarrier(cmd);
  });

  EnvironmentMap map;
  map.image.width = width;
  map.image.height = height;
  map.image.rgba.resize(texels * 4);
  std::memcpy(map.image.rgba.data(), radiance_buffer.mapped(), texels * sizeof(glm::vec4));
  const auto* sunlight = reinterpret_cast<const float*>(sun_buffer.mapped());
  map.sun_irradiance = {sunlight[0], sunlight[1], sunlight[2]};
  return map;
}

}  // namespace aerial
