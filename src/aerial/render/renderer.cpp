#include "aerial/render/renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "aerial/core/format_number.h"
#include "aerial/error.h"
#include "aerial/image/resample.h"
#include "aerial/render/shadow_tile_region.h"
#include "aerial/render/shadow_uniforms.h"
#include "aerial/render/sky_view_layout.h"
#include "froxel/sun_high_variant.h"
#include "aerial/render/surface_reads.h"
#include "aerial/scene/terrain.h"
#include "aerial/terrain/terrain_chunk.h"

namespace aerial {
namespace {

using vk::kSampled;
using vk::kUniform;

// The aerial mode's specialization constant kAerialPerPixel (frame.glsl).
int32_t PerPixel(AerialMode mode) {
  switch (mode) {
    case AerialMode::kFroxel: return 0;
    case AerialMode::kPerPixel: return 1;
    case AerialMode::kTableDifference: return 2;
  }
  throw Error("aerial mode", std::to_string(int(mode)), "froxel, per-pixel or table-difference");
}

// Terrain chunk slots on the GPU: the default view at 720p draws a few hundred chunks and walks
// through about as many coarser ones; the rest keeps chunks around for a camera that moves.
constexpr uint32_t kTerrainChunkSlots = 8192;
// The ground's draws are numbered as opaque.vert's kGroundDetailInstance: its albedo detail.
constexpr uint32_t kGroundDetailInstance = 1;

// Opaque and transparent meshes read the same resources: the atmosphere and frame blocks, the
// transmittance and irradiance tables (lighting), the multiple density table (marched per-pixel
// mode), the froxels, the shadow block and map (shadow.glsl, AERIAL_SHADOW_BINDING 8), the screen's cached
// sun visibility (opaque_fragment.glsl) and the scattering tables (table-difference mode,
// mesh_tables.glsl).
const vk::SlotLayout kMeshSlots = {
    {"AtmosphereBlock", kUniform},        {"FrameBlock", kUniform},
    {"transmittance_texture", kSampled},  {"irradiance_texture", kSampled},
    {"multiple_density_texture", kSampled}, {"rayleigh_froxels", kSampled},
    {"mie_froxels", kSampled},            {"transmittance_froxels", kSampled},
    {"ShadowBlock", kUniform},            {"shadow_map", kSampled},
    {"cached_sun_visibility", kSampled},  {"rayleigh_texture", kSampled},
    {"mie_texture", kSampled},            {"multiple_texture", kSampled}};

// The sky-view pass (sky_view.comp) and the sky (sky.frag) bind these resources, the sky-view
// table written by the one (sky_view_type: storage images) and read by the other (sampled).
vk::SlotLayout SkySlots(::vk::DescriptorType sky_view_type) {
  return {{"AtmosphereBlock", kUniform},      {"FrameBlock", kUniform},
          {"transmittance_texture", kSampled}, {"rayleigh_texture", kSampled},
          {"mie_texture", kSampled},           {"multiple_texture", kSampled},
          {"irradiance_texture", kSampled},    {"rayleigh_sky", sky_view_type},
          {"mie_sky", sky_view_type},          {"background_sky", sky_view_type}};
}

// The sky-view pass also reads the correction lattice that the correction pass writes.
vk::SlotLayout SkyViewSlots() {
  vk::SlotLayout slots = SkySlots(vk::kStorageImage);
  slots.push_back({"rayleigh_correction", vk::kStorageImage});
  slots.push_back({"mie_correction", vk::kStorageImage});
  return slots;
}

vk::SlotLayout SkyViewCorrectionSlots() {
  return {{"AtmosphereBlock", kUniform}, {"FrameBlock", kUniform}, {"transmittance_texture", kSampled},
          {"rayleigh_texture", kSampled}, {"rayleigh_correction", vk::kStorageImage}, {"mie_correction", vk::kStorageImage}};
}

// Its constants: 0 (frame.glsl's kAerialPerPixel, unread) keeps its default; 4 the variant for a
// high sun.
vk::ComputePipeline SkyViewCorrectionPipeline(const vk::Context& context, bool sun_high) {
  return vk::ComputePipeline(context, "frame/sky_view_correction.comp", SkyViewCorrectionSlots(),
                             sizeof(kSkyViewSize) + 2 * sizeof(int), {0, 0, 0, 0, sun_high ? 1 : 0});
}

// The mesh shaders' specialization constants: 0 aerial perspective per pixel (frame.glsl), 1 sun
// shadows (shadow.glsl), 2 the sun's part of the lighting in surface.frag (SurfaceLight), 3 the
// sun visibility read from the cache, 4 the variant for a high sun, 5 the froxels read per vertex,
// 6 the reads a benchmark leaves out (opaque_fragment.glsl), 7 the ground's detail (ground_detail.glsl),
// 8 the aerial perspective applied in a full-screen pass after the opaque pass (opaque_fragment.glsl).
struct MeshVariant {
  SurfaceLight light = SurfaceLight::kSunAndSky;
  SunVisibilitySource source = SunVisibilitySource::kLookUp;
  bool sun_high = false;
  bool froxels_per_vertex = false;
};

std::vector<int32_t> MeshConstants(const RendererOptions& options, const MeshVariant& variant = {}) {
  const int32_t left_out = (options.left_out_reads.froxels ? 1 : 0) | (options.left_out_reads.sun_visibility ? 2 : 0) |
                           (options.left_out_reads.shading ? 4 : 0);
  return {PerPixel(options.mode), options.shadows ? 1 : 0, variant.light == SurfaceLight::kSunAndSky ? 1 : 0,
          variant.source == SunVisibilitySource::kCache ? 1 : 0, variant.sun_high ? 1 : 0,
          variant.froxels_per_vertex ? 1 : 0, left_out, options.ground_detail ? 1 : 0,
          AerialPerspectiveInFullScreenPass(options) ? 1 : 0};
}

vk::GraphicsPipelineCreateInfo MeshPipeline(const std::string& vertex, const std::string& fragment,
                                            bool blended, std::vector<int32_t> constants,
                                            std::vector<vk::Format> color_formats = {vk::kRgba32f}) {
  return {.vertex_shader = vertex,
          .fragment_shader = fragment,
          .slots = kMeshSlots,
          .vertex_stride = sizeof(Vertex),
          .attributes = {{vk::kRgb32f, offsetof(Vertex, position)},
                         {vk::kRgb32f, offsetof(Vertex, normal)},
                         {vk::kRgb32f, offsetof(Vertex, albedo)},
                         {vk::kR32f, offsetof(Vertex, opacity)}},
          .color_formats = std::move(color_formats),
          .depth_format = vk::kDepth32f,
          .depth_write = !blended,
          .alpha_blend = blended,
          .dynamic_cull_mode = !blended,
          .specialization = std::move(constants)};
}

// The sky: a full-screen triangle at depth 0 whose test (EQUAL against the depth cleared to 0,
// reversed Z) passes only where no geometry was drawn, so each pixel runs one shader or the other.
// Its constants: 0 aerial perspective per pixel (frame.glsl), 4 the variant for a high sun.
vk::GraphicsPipelineCreateInfo SkyPipeline(AerialMode mode, bool sun_high) {
  return {.vertex_shader = "frame/sky.vert",
          .fragment_shader = "frame/sky.frag",
          .slots = SkySlots(kSampled),
          .color_formats = {vk::kRgba32f},
          .depth_format = vk::kDepth32f,
          .depth_write = false,
          .depth_compare = vk::kDepthEqual,
          .specialization = {PerPixel(mode), 0, 0, 0, sun_high ? 1 : 0}};
}

// The aerial perspective's full-screen pass (aerial_composite.frag): a triangle over the screen at
// depth 0, drawn where the opaque pass left a depth nearer than that (reversed Z), reading the
// surfaces' radiance (binding 14) besides what the mesh passes read. Its constants are the mesh
// passes' that it shares: 0 the aerial mode, 1 shadows (the marched path's sun visibility) and 4
// the variant for a high sun.
vk::GraphicsPipeline CompositePipeline(const vk::Context& context, const RendererOptions& o, bool sun_high) {
  vk::SlotLayout slots = kMeshSlots;
  slots.push_back({"surface_radiance", kSampled});
  return vk::GraphicsPipeline(context, {.vertex_shader = "frame/fullscreen.vert",
                                        .fragment_shader = "frame/aerial_composite.frag",
                                        .slots = std::move(slots),
                                        .color_formats = {vk::kRgba32f},
                                        .depth_format = vk::kDepth32f,
                                        .depth_write = false,
                                        .depth_compare = vk::kDepthFarther,
                                        .specialization = {PerPixel(o.mode), o.shadows ? 1 : 0, 0, 0, sun_high ? 1 : 0}});
}

// Froxel mode: the sun's disc over the sky, a triangle around it (sun_disc.vert) drawn where the
// sky was (EQUAL against the depth cleared to 0) and added to it (alpha 0 through the
// premultiplied blend).
std::optional<vk::GraphicsPipeline> SunDiscPipeline(const vk::Context& context, AerialMode mode) {
  if (mode != AerialMode::kFroxel) return std::nullopt;
  return vk::GraphicsPipeline(context, {.vertex_shader = "frame/sun_disc.vert",
                                        .fragment_shader = "frame/sun_disc.frag",
                                        .slots = {{"AtmosphereBlock", kUniform},
                                                  {"FrameBlock", kUniform},
                                                  {"background_sky", kSampled}},
                                        .color_formats = {vk::kRgba32f},
                                        .depth_format = vk::kDepth32f,
                                        .depth_write = false,
                                        .depth_compare = vk::kDepthEqual,
                                        .alpha_blend = true});
}

vk::ImageCreateInfo SkyViewImage() {
  return {.extent = {uint32_t(kSkyViewSize[0]), uint32_t(kSkyViewSize[1]), 1}};
}

vk::ImageCreateInfo SkyViewLatticeImage() {
  return {.extent = {uint32_t(kSkyViewLatticeSize[0]), uint32_t(kSkyViewLatticeSize[1]), 1}};
}

vk::ImageCreateInfo Target(const RenderOptions& o, vk::Format format) {
  return vk::RenderTargetInfo(uint32_t(o.render_width()), uint32_t(o.render_height()), format);
}

// The screen's sun visibility (opaque_fragment.glsl), in float: a cached frame is then the frame
// that wrote it, to the bit. Without shadows nothing reads it, and one texel stands in.
constexpr vk::Format kSunVisibilityFormat = vk::kR32f;

vk::ImageCreateInfo SunVisibilityTarget(const RenderOptions& o) {
  return o.shadows ? Target(o, kSunVisibilityFormat) : vk::RenderTargetInfo(1, 1, kSunVisibilityFormat);
}

vk::ImageCreateInfo SurfaceRadianceTarget(const RendererOptions& o) {
  return AerialPerspectiveInFullScreenPass(o) ? Target(o, vk::kRgba32f) : vk::RenderTargetInfo(1, 1, vk::kRgba32f);
}

vk::GraphicsPipeline OpaquePipeline(const vk::Context& context, const RendererOptions& o, MeshVariant variant) {
  if (variant.source == SunVisibilitySource::kLookUpAndCache)
    return vk::GraphicsPipeline(context, MeshPipeline("frame/opaque.vert", "frame/opaque_caching.frag", false,
                                                      MeshConstants(o, variant), {vk::kRgba32f, kSunVisibilityFormat}));
  return vk::GraphicsPipeline(context, MeshPipeline("frame/opaque.vert", "frame/opaque.frag", false,
                                                    MeshConstants(o, variant)));
}

// The opaque pipelines of one way of reading the froxels; with shadows, also those of the screen's
// sun visibility (opaque_fragment.glsl).
OpaquePipelines MakeOpaquePipelines(const vk::Context& context, const RendererOptions& o, MeshVariant variant) {
  OpaquePipelines pipelines{.look_up = OpaquePipeline(context, o, variant)};
  if (o.shadows) {
    pipelines.look_up_and_cache = OpaquePipeline(
        context, o, {.source = SunVisibilitySource::kLookUpAndCache, .sun_high = variant.sun_high,
                     .froxels_per_vertex = variant.froxels_per_vertex});
    pipelines.cache = OpaquePipeline(context, o, {.source = SunVisibilitySource::kCache, .sun_high = variant.sun_high,
                                                  .froxels_per_vertex = variant.froxels_per_vertex});
  }
  return pipelines;
}

MeshPipelines MakeMeshPipelines(const vk::Context& context, const RendererOptions& o, bool sun_high) {
  MeshPipelines pipelines{
      .per_pixel = MakeOpaquePipelines(context, o, {.sun_high = sun_high}),
      .transparent = vk::GraphicsPipeline(context, MeshPipeline("frame/transparent.vert", "frame/transparent.frag",
                                                                true, MeshConstants(o, {.sun_high = sun_high})))};
  if (o.mode == AerialMode::kFroxel && o.surface_froxel_reads != SurfaceFroxelReads::kPerPixel &&
      !AerialPerspectiveInFullScreenPass(o))
    pipelines.per_vertex = MakeOpaquePipelines(context, o, {.sun_high = sun_high, .froxels_per_vertex = true});
  if (AerialPerspectiveInFullScreenPass(o)) pipelines.composite = CompositePipeline(context, o, sun_high);
  return pipelines;
}

std::vector<Mesh> ReferenceTerrain(const Scene& scene, const RendererOptions& options, double R) {
  if (!scene.terrain || options.terrain != TerrainMode::kStaticMesh || !options.passes.terrain) return {};
  return {BuildTerrainMesh(R)};
}

// Everything that casts a shadow, around the scene's origin: the terrain (to kTerrainRadiusM,
// with mountains up to kTerrainMaxHeightM and the sphere's 0.8 km drop at its edge well inside
// 10 km more) and the opaque meshes; and the casters' top and the receivers' bottom, as distances
// from the planet's centre (0, 0, -R).
CasterBounds SceneCasterBounds(const Scene& scene, double R) {
  CasterBounds bounds{.center = glm::dvec3(0.0),
                      .radius_m = scene.terrain ? kTerrainRadiusM + 10e3 : 0.0,
                      .top_radius_m = R + (scene.terrain ? kTerrainMaxHeightM : 0.0),
                      .bottom_radius_m = R + (scene.terrain ? kTerrainMinHeightM : 0.0)};
  const glm::dvec3 planet_center(0.0, 0.0, -R);
  for (const Mesh& mesh : scene.meshes)
    for (const Vertex& v : mesh.vertices) {
      const double from_center = glm::length(glm::dvec3(v.position) - planet_center);
      bounds.bottom_radius_m = std::min(bounds.bottom_radius_m, from_center);
      if (mesh.transparent) continue;
      bounds.radius_m = std::max(bounds.radius_m, double(glm::length(v.position)));
      bounds.top_radius_m = std::max(bounds.top_radius_m, from_center);
    }
  return bounds;
}

// How far from the scene's origin a surface may lie: the terrain's chunks (a square of
// kRootSizeM, whose corners are at the bare sphere, kRootSizeM^2 / 4R below the origin's plane,
// and whose mountains are at most kTerrainMaxHeightM high; the fixed mesh lies inside it) and the
// meshes' vertices.
double SceneRadiusM(const Scene& scene, double R) {
  const double half_diagonal = terrain::kRootSizeM * std::sqrt(0.5);
  double radius = scene.terrain ? half_diagonal + kTerrainMaxHeightM + half_diagonal * half_diagonal / (2.0 * R) : 0.0;
  for (const Mesh& mesh : scene.meshes)
    for (const Vertex& v : mesh.vertices) radius = std::max(radius, double(glm::length(v.position)));
  return radius;
}

std::unique_ptr<TerrainChunkCache> TerrainCache(const vk::Context& context, const Scene& scene,
                                                const RendererOptions& options, double R) {
  if (!scene.terrain || options.terrain != TerrainMode::kLod) return nullptr;
  return std::make_unique<TerrainChunkCache>(context, R, kTerrainChunkSlots, options.frames_in_flight,
                                             options.share_built_terrain ? &terrain::BuiltChunks::Shared() : nullptr,
                                             options.terrain_selector == TerrainSelector::kGpu);
}

// The options with what they leave to the device resolved for it: TerrainSelector::kAuto and
// terrain_builds_in_background.
RendererOptions ForTheDevice(const vk::Context& context, RendererOptions options) {
  if (options.terrain_selector == TerrainSelector::kAuto)
    options.terrain_selector = context.cpu_device() ? TerrainSelector::kCpu : TerrainSelector::kGpu;
  if (!options.terrain_builds_in_background) options.terrain_builds_in_background = !context.cpu_device();
  return options;
}

std::unique_ptr<GpuChunkSelection> GpuTerrainSelection(const vk::Context& context, const TerrainChunkCache* cache,
                                                       const RendererOptions& options) {
  if (!cache || options.terrain_selector != TerrainSelector::kGpu) return nullptr;
  return std::make_unique<GpuChunkSelection>(context, kTerrainChunkSlots, terrain::kChunkVertices,
                                             kGroundDetailInstance, options.frames_in_flight);
}

std::unique_ptr<GpuShadowCasters> GpuCasterSelection(const vk::Context& context, const TerrainChunkCache* cache,
                                                     const RendererOptions& options) {
  if (!cache || options.terrain_selector != TerrainSelector::kGpu || !options.shadows) return nullptr;
  return std::make_unique<GpuShadowCasters>(context, kTerrainChunkSlots, terrain::kChunkVertices,
                                            options.frames_in_flight);
}

}  // namespace

uint64_t GpuTerrainSelectionBytes(const RenderOptions& o) {
  return GpuChunkSelection::MemoryBytes(kTerrainChunkSlots, o.frames_in_flight, true) +
         (o.shadows ? GpuShadowCasters::MemoryBytes(kTerrainChunkSlots, o.frames_in_flight) : 0);
}

FrameMemory EstimateFrameMemory(const RenderOptions& o) {
  const uint64_t rendered = uint64_t(o.render_width()) * o.render_height();
  const uint64_t output = uint64_t(o.width) * o.height;
  const uint64_t sky_view = (3 * uint64_t(kSkyViewSize[0]) * kSkyViewSize[1] +
                             2 * uint64_t(kSkyViewLatticeSize[0]) * kSkyViewLatticeSize[1]) * 16;
  const uint64_t froxels = uint64_t(o.froxels.width) * o.froxels.height * o.froxels.depth;
  // The per-pixel modes' opaque pass writes its surfaces' radiance (rgba32f) for the full-screen
  // pass that applies their aerial perspective.
  const uint64_t surface_radiance = o.mode == AerialMode::kFroxel ? 0 : rendered * 16;
  return {
      .targets = rendered * (16 + 4) + surface_radiance + sky_view,  // rgba32f radiance, d32 depth
      // ReadImageFloats holds two copies of the rendered pixels at once (16 bytes each); the
      // upscaled image and the encoded file at most 16 bytes per output pixel each.
      .readback = rendered * 32 + output * 32,
      .froxels = 3 * froxels * 16,  // Rayleigh, Mie, transmittance; rgba32f
      // The chunk slots' vertices and, as a GPU device selects them by default, its selection's
      // buffers (the frame's and the shadow casters').
      .terrain = uint64_t(kTerrainChunkSlots) * terrain::kChunkVertices * sizeof(Vertex) + GpuTerrainSelectionBytes(o),
      .shadows = ShadowMap::MemoryBytes(o.shadows) + (o.shadows ? rendered * 4 : 0),  // + r32f visibility
  };
}

void RenderOptions::Validate() const {
  try {
    CheckImageSize(width, height);
  } catch (const Error& e) {
    throw Error("RenderOptions::width/height", e.value(), e.allowed());
  }
  if (!(render_scale >= 0.25 && render_scale <= 1.0))
    throw Error("RenderOptions::render_scale", FormatNumber(render_scale), "in [0.25, 1]");
  if (!(terrain_error_px >= 0.25 && terrain_error_px <= 64.0))
    throw Error("RenderOptions::terrain_error_px", FormatNumber(terrain_error_px), "in [0.25, 64]");
  froxels.Validate();
}

int RenderOptions::render_width() const { return std::max(1, int(std::lround(width * render_scale))); }
int RenderOptions::render_height() const { return std::max(1, int(std::lround(height * render_scale))); }

Renderer::Renderer(const AtmosphereTables& tables, const Scene& scene, const RendererOptions& options)
    : tables_(tables),
      options_(ForTheDevice(tables.context(), (options.Validate(), options))),
      geometry_(tables.context(), scene, options.frames_in_flight,
                ReferenceTerrain(scene, options, tables.atmosphere().bottom_radius_m)),
      terrain_(TerrainCache(tables.context(), scene, options_, tables.atmosphere().bottom_radius_m)),
      gpu_terrain_(GpuTerrainSelection(tables.context(), terrain_.get(), options_)),
      gpu_casters_(GpuCasterSelection(tables.context(), terrain_.get(), options_)),
      froxels_(tables.context(), options.froxels),
      depth_(tables.context(), Target(options, vk::kDepth32f)),
      output_(tables.context(), Target(options, vk::kRgba32f)),
      sun_visibility_(tables.context(), SunVisibilityTarget(options)),
      surface_radiance_(tables.context(), SurfaceRadianceTarget(options)),
      sky_rayleigh_(tables.context(), SkyViewImage()),
      sky_mie_(tables.context(), SkyViewImage()),
      sky_background_(tables.context(), SkyViewImage()),
      sky_rayleigh_correction_(tables.context(), SkyViewLatticeImage()),
      sky_mie_correction_(tables.context(), SkyViewLatticeImage()),
      shadow_map_(tables.context(), options.shadows),
      casters_(SceneCasterBounds(scene, tables.atmosphere().bottom_radius_m)),
      sky_view_correction_(SkyViewCorrectionPipeline(tables.context(), false)),
      sky_view_(tables.context(), "frame/sky_view.comp", SkyViewSlots(), sizeof(kSkyViewSize)),
      scene_radius_m_(SceneRadiusM(scene, tables.atmosphere().bottom_radius_m)),
      mesh_(MakeMeshPipelines(tables.context(), options, false)),
      sky_(tables.context(), SkyPipeline(options.mode, false)),
      surface_(tables.context(), MeshPipeline("frame/opaque.vert", "frame/surface.frag", false, MeshConstants(options_))),
      sun_disc_(SunDiscPipeline(tables.context(), options.mode)) {
  if (options.frames_in_flight < 1) throw Error("frames in flight", "0", "at least 1");
  for (uint32_t slot = 0; slot < options.frames_in_flight; ++slot) {
    frame_buffers_.emplace_back(tables.context(), vk::UniformBufferInfo(sizeof(FrameUniforms)));
    shadow_buffers_.emplace_back(tables.context(), vk::UniformBufferInfo(sizeof(ShadowUniforms)));
    timers_.push_back(std::make_unique<vk::GpuTimer>(tables.context()));
    opaque_commands_.emplace_back(tables.context());
    shadow_commands_.emplace_back(tables.context());
  }
  tables.context().Submit([&](const auto& cmd) {
    for (const vk::Image* image : {&depth_, &output_, &sun_visibility_, &surface_radiance_, &sky_rayleigh_, &sky_mie_,
                                   &sky_background_, &sky_rayleigh_correction_, &sky_mie_correction_})
      image->InitializeLayout(cmd);
  });
}

Renderer::~Renderer() = default;

void Renderer::SetTerrainErrorPx(double error_px) {
  RendererOptions changed = options_;
  changed.terrain_error_px = error_px;
  changed.Validate();
  options_ = changed;
  shadow_selection_whole_ = false;  // the shadow pass selects with the same bound
}

void Renderer::SetRenderScale(double render_scale) {
  if (render_scale == options_.render_scale) return;
  RendererOptions changed = options_;
  changed.render_scale = render_scale;
  changed.Validate();
  options_ = changed;
  // The targets of the render size; the pipelines, tables, froxel volume and terrain stay. The
  // next frame's uniforms hold the new viewport, so nothing kept for the old size is reused.
  const vk::Context& context = tables_.context();
  depth_ = vk::Image(context, Target(options_, vk::kDepth32f));
  output_ = vk::Image(context, Target(options_, vk::kRgba32f));
  sun_visibility_ = vk::Image(context, SunVisibilityTarget(options_));
  surface_radiance_ = vk::Image(context, SurfaceRadianceTarget(options_));
  context.Submit([&](const auto& cmd) {
    for (const vk::Image* image : {&depth_, &output_, &sun_visibility_, &surface_radiance_})
      image->InitializeLayout(cmd);
  });
}

terrain::LodView Renderer::FrameLodView(const Scene& scene) const {
  double aspect = double(options_.render_width()) / double(options_.render_height());
  // The terrain's detail follows the render scale, its floor too: a frame drawn smaller (the
  // viewer's dynamic resolution while the view moves) keeps the error bound in its own pixels, so
  // that its triangles cover as many of its pixels as a full frame's cover of the window's.
  const int min_height_px = std::max(1, int(std::lround(terrain::kLodMinHeightPx * options_.render_scale)));
  return terrain::MakeLodView(scene.camera, aspect, options_.render_height(), options_.terrain_error_px,
                              tables_.atmosphere().bottom_radius_m, min_height_px);
}

// The chunks to draw, nearest first (terrain/lod_selection.h), built as needed; a still camera
// keeps its last frame's (TerrainSelectionKept).
void Renderer::SelectTerrain(const Scene& scene, bool complete, uint32_t slot) {
  gpu_terrain_due_ = false;
  if (!terrain_ || !options_.passes.terrain) {
    terrain_chunks_.clear();
    return;
  }
  // The first frame builds all it needs, so that a window opens on the whole terrain.
  terrain_->BeginFrame(complete || frames_recorded_ == 0 ? 0.0 : options_.terrain_build_budget_ms);
  terrain::LodView view = FrameLodView(scene);
  view.occlusion_culling = options_.terrain_occlusion_culling;
  if (gpu_terrain_) {
    PrepareGpuTerrainSelection(view, complete || frames_recorded_ == 0, slot);
    return;
  }
  if (TerrainSelectionKept(view == terrain_selected_for_, terrain_deferred_ == 0)) {
    // Found again so that the cache, which evicts the chunk used longest ago, keeps them.
    for (const terrain::SelectedChunk& chunk : terrain_chunks_) terrain_->Find(chunk.id);
  } else {
    terrain_selected_for_ = view;
    frame_info_.terrain_selected = true;
    terrain::Selection selection = terrain::SelectChunks(view, *terrain_);
    if (selection.chunks != terrain_chunks_) ++terrain_changes_;
    terrain_chunks_ = std::move(selection.chunks);
    terrain_hidden_ = selection.hidden;
    terrain_deferred_ = selection.deferred;
  }
  size_t indices = 0;
  for (const terrain::SelectedChunk& chunk : terrain_chunks_) indices += terrain::ChunkIndexRange(chunk.skirts).count;
  frame_info_.chunks = terrain_chunks_.size();
  frame_info_.triangles = indices / 3;
  frame_info_.deferred = terrain_deferred_;
  frame_info_.hidden = terrain_hidden_;
  frame_info_.built = terrain_->built_this_frame();
}

void Renderer::PrepareGpuTerrainSelection(const terrain::LodView& view, bool complete, uint32_t slot) {
  // The chunks the last frame asked to build join the tree (they were built beside that frame).
  terrain_->FinishBackgroundBuilds();
  // The slot's last frame has completed, and with it the selections it recorded, if any. What they
  // asked for is built beside this frame, which draws the parents meanwhile (or before it records,
  // where the device runs its frame on the CPU's cores); a one-off frame builds it first.
  std::vector<terrain::ChunkId> requested;
  if (gpu_casters_) requested = gpu_casters_->ReadFeedback(slot, *terrain_);
  if (GpuChunkSelection::Feedback feedback = gpu_terrain_->ReadFeedback(slot);
      feedback.generation > gpu_terrain_feedback_.generation) {
    for (uint32_t drawn : feedback.drawn_slots) terrain_->Used(drawn);
    requested.insert(requested.begin(), feedback.requested.begin(), feedback.requested.end());
    gpu_terrain_feedback_ = std::move(feedback);
  }
  if (complete || !*options_.terrain_builds_in_background)
    terrain_->Build(requested);
  else
    terrain_->BuildInBackground(requested);
  int deferred = gpu_terrain_feedback_.deferred;
  if (complete) {
    // Every chunk the GPU may ask for: those of the CPU's rule without the horizon, which hides
    // less than the GPU's (and could hide chunks that the GPU draws).
    terrain::LodView unculled = view;
    unculled.occlusion_culling = false;
    deferred = terrain::SelectChunks(unculled, *terrain_).deferred;
  }
  ApplyTerrainSlotChanges();
  // The same view over the same tree draws what the last selection drew.
  gpu_terrain_due_ = !(view == terrain_selected_for_) || gpu_terrain_->tree_changed();
  if (gpu_terrain_due_) {
    terrain_selected_for_ = view;
    ++terrain_changes_;
    frame_info_.terrain_selected = true;
  }
  // What the last selection read back drew: a frame or more late.
  frame_info_.chunks = gpu_terrain_feedback_.per_pixel + gpu_terrain_feedback_.per_vertex;
  frame_info_.triangles = gpu_terrain_feedback_.indices / 3;
  frame_info_.hidden = gpu_terrain_feedback_.hidden;
  frame_info_.deferred = deferred;
  frame_info_.built = terrain_->built_this_frame();
  // Until the feedback of the selection that draws is read, it may ask for chunks.
  terrain_feedback_pending_ =
      !complete && (gpu_terrain_due_ || gpu_terrain_feedback_.generation != gpu_terrain_->generation());
}

void Renderer::ApplyTerrainSlotChanges() {
  const std::vector<TerrainChunkCache::SlotChange> changes = terrain_->TakeSlotChanges();
  for (const TerrainChunkCache::SlotChange& change : changes) {
    if (change.info)
      gpu_terrain_->Insert(change.slot, change.id, *change.info, PerPixelReadsWithinM(*change.info));
    else
      gpu_terrain_->Remove(change.slot);
  }
  if (gpu_casters_) gpu_casters_->Apply(changes);
}

void Renderer::RecordTerrainSelection(const vk::CommandBuffer& cmd, uint32_t slot) {
  if (!gpu_terrain_due_) return;
  vk::GpuTimer& timer = *timers_[slot];
  timer.Begin(cmd, "terrain selection");
  gpu_terrain_->Record(cmd, *terrain_selected_for_, slot);
  timer.End(cmd);
}

double Renderer::PerPixelReadsWithinM(const terrain::ChunkInfo& info) const {
  switch (options_.surface_froxel_reads) {
    case SurfaceFroxelReads::kPerPixel: return std::numeric_limits<double>::infinity();
    case SurfaceFroxelReads::kPerVertexWhereThin:
      return aerial::PerPixelReadsWithinM(options_.froxels, MakeAirScales(tables_.atmosphere()), info.longest_edge_m,
                                          info.largest_rise_m);
    case SurfaceFroxelReads::kPerVertex:
    case SurfaceFroxelReads::kFullScreenPass: break;
  }
  return 0.0;
}

// When the sky-view table is remade: frame_cache_policy.h (SkyViewReusable), and after a band of
// its correction lattice was.
bool Renderer::SkyViewStale(bool exact, bool lattice_remade) {
  SkyViewKey key = MakeSkyViewKey(frame_uniforms_);
  if (!lattice_remade && SkyViewReusable(sky_view_key_, key, exact)) return false;
  sky_view_key_ = key;
  frame_info_.sky_view_updated = true;
  return true;
}

// The correction of the tables' sky inscatter at the sky-view table's lattice nodes
// (sky_view_correction.comp; with the 3D tables its invocations return at once), in the bands
// marked in `remake` (frame_cache_policy.h, SkyViewLatticeBandsToRemake), one dispatch per run
// of neighbouring bands. It is recorded before the froxel build and followed by a barrier, so
// that the froxel build and the sky-view pass that reads it still run side by side.
void Renderer::RecordSkyViewCorrection(const vk::CommandBuffer& cmd, const vk::Buffer& frame,
                                       const std::array<bool, kSkyViewLatticeBands>& remake) {
  SkyViewKey key = MakeSkyViewKey(frame_uniforms_);
  for (int band = 0; band < kSkyViewLatticeBands;) {
    if (!remake[band]) {
      ++band;
      continue;
    }
    int end = band;
    while (end < kSkyViewLatticeBands && remake[end]) sky_view_lattice_keys_[end++] = key;
    struct {
      std::array<int, 2> size;
      int first_row, end_row;
    } constants{kSkyViewSize, SkyViewLatticeBandRows(band).first, SkyViewLatticeBandRows(end - 1).end};
    SkyViewCorrectionPipelineFor().Dispatch(cmd,
                                  {vk::UniformBufferSlot{&tables_.uniform_buffer()}, vk::UniformBufferSlot{&frame},
                                   tables_.Sampled(tables_.transmittance()), tables_.Sampled(tables_.rayleigh()),
                                   vk::StorageImageSlot{&sky_rayleigh_correction_},
                                   vk::StorageImageSlot{&sky_mie_correction_}},
                                  {uint32_t(kSkyViewLatticeSize[0]), uint32_t(constants.end_row - constants.first_row), 1},
                                  {8, 8, 1}, &constants);
    band = end;
  }
}

void Renderer::RecordSkyView(const vk::CommandBuffer& cmd, const vk::Buffer& frame) {
  sky_view_.Dispatch(cmd,
                     {vk::UniformBufferSlot{&tables_.uniform_buffer()}, vk::UniformBufferSlot{&frame},
                      tables_.Sampled(tables_.transmittance()), tables_.Sampled(tables_.rayleigh()),
                      tables_.Sampled(tables_.mie()), tables_.Sampled(tables_.multiple()),
                      tables_.Sampled(tables_.irradiance()),
                      vk::StorageImageSlot{&sky_rayleigh_}, vk::StorageImageSlot{&sky_mie_},
                      vk::StorageImageSlot{&sky_background_}, vk::StorageImageSlot{&sky_rayleigh_correction_},
                      vk::StorageImageSlot{&sky_mie_correction_}},
                     {uint32_t(kSkyViewSize[0]), uint32_t(kSkyViewSize[1]), 1}, {8, 8, 1},
                     kSkyViewSize.data());
}

// The cascades are fitted to every frame's camera (cheap), keeping the windows the shadow map holds
// while their slices fit (shadow_cascades.h), and a tile of the shadow map is redrawn only when
// what it shows changed (frame_cache_policy.h: its window, the sun, one tile a frame, or its
// terrain casters as its texels resolve them).
void Renderer::RecordShadowMap(const vk::CommandBuffer& cmd, const Scene& scene, uint32_t slot, bool exact) {
  const glm::dvec3 sun = scene.sun.Direction();
  const CascadeFitInput fit{.camera = scene.camera,
                            .aspect = double(options_.render_width()) / options_.render_height(),
                            .sun = sun,
                            .tile_texels = kShadowTileTexels,
                            .casters = casters_};
  const glm::dvec3 camera_up = glm::normalize(glm::dvec3(scene.camera.position) +
                                              glm::dvec3(0.0, 0.0, tables_.atmosphere().bottom_radius_m));
  const std::array<bool, kShadowCascades> keep_sun = ShadowTilesKeepingTheirSun(
      shadow_key_, sun, exact, still_view_ ? 0.0 : ShadowReachM(sun, camera_up, casters_));
  shadow_cascades_ = FitShadowCascades(fit, HeldShadowWindows(shadow_key_, exact), keep_sun);
  if (!options_.shadows) return;
  const std::array<bool, kShadowCascades> moved = ShadowWindowsMoved(shadow_key_, shadow_cascades_);
  const bool caught_up = shadow_key_ && ShadowTilesCaughtUp(shadow_key_->cascades, sun);
  if (!shadow_key_) shadow_key_.emplace();
  ShadowKey& key = *shadow_key_;
  if (ShadowMapKept(still_view_, shadow_selection_whole_, moved, caught_up)) return;
  const terrain::LodView lod_view = FrameLodView(scene);
  const bool select_terrain = terrain_ && options_.passes.terrain;
  std::array<std::optional<TileTexels>, kShadowCascades> redraw{};
  ShadowTerrain drawn;  // the chunks each redrawn tile draws
  for (int i = 0; i < kShadowCascades; ++i) {
    key.cascades[i] = shadow_cascades_[i];
    // A tile waiting for its turn to catch up with the sun is not redrawn for chunks that arrived.
    if (keep_sun[i] && !moved[i]) continue;
    if (gpu_casters_ && select_terrain && GpuShadowCasters::Selects(i)) {
      if (RecordGpuCasters(cmd, i, lod_view, slot, moved[i], exact)) {
        redraw[i] = WholeTile(kShadowTileTexels);
        ++frame_info_.shadow_tiles_redrawn;
      }
      continue;
    }
    if (CastersKept(key.selections[i], lod_view, shadow_cascades_[i], moved[i])) continue;
    std::vector<terrain::SelectedChunk> casters;
    if (select_terrain) {
      CascadeCasters selected = SelectCascadeCasters(lod_view, shadow_cascades_[i], *terrain_);
      key.selections[i] = MakeCasterSelection(lod_view, shadow_cascades_[i], selected);
      casters = std::move(selected.chunks);
      if (gpu_terrain_) ApplyTerrainSlotChanges();  // the chunks it built, for the GPU's trees
    }
    if (!ShadowTileRedrawn(moved[i], casters, key.casters[i])) continue;
    // A window that held, with casters that changed: only where they changed, when that is known
    // and small (shadow_tile_region.h).
    if (options_.shadow_tile_regions && select_terrain && !moved[i] && !key.casters[i].empty())
      redraw[i] = ChangedCastersTexels(shadow_cascades_[i], kShadowTileTexels, key.casters[i], casters, *terrain_);
    if (!redraw[i]) {
      redraw[i] = WholeTile(kShadowTileTexels);
      drawn[i] = casters;
      ++frame_info_.shadow_tiles_redrawn;
    } else if (!redraw[i]->Empty()) {
      drawn[i] = CastersReaching(shadow_cascades_[i], kShadowTileTexels, casters, *redraw[i], *terrain_);
      ++frame_info_.shadow_tile_regions_redrawn;
    }
    key.casters[i] = std::move(casters);
  }
  shadow_selection_whole_ = !select_terrain || !gpu_casters_ || gpu_casters_->whole();
  for (int i = 0; i < kShadowCascades && select_terrain; ++i)
    if (!gpu_casters_ || !GpuShadowCasters::Selects(i))
      shadow_selection_whole_ = shadow_selection_whole_ && key.selections[i] && key.selections[i]->whole;
  if (frame_info_.shadow_tiles_redrawn + frame_info_.shadow_tile_regions_redrawn == 0) return;
  RecordedDraws recorded = shadow_map_.Record(cmd, shadow_cascades_, redraw, scene.camera.position, geometry_,
                                              terrain_.get(), drawn, select_terrain ? gpu_casters_.get() : nullptr,
                                              shadow_commands_[slot]);
  frame_info_.draws += recorded.draws;
  frame_info_.draw_binds += recorded.binds;
  vk::FullBarrier(cmd);  // the froxel pass and the surfaces read it
  frame_info_.shadow_map_updated = true;
}

// An exact frame selects every tile's casters again, over every chunk the CPU's rule would draw,
// built first: the GPU then asks for none.
bool Renderer::RecordGpuCasters(const vk::CommandBuffer& cmd, int cascade, const terrain::LodView& lod_view,
                                uint32_t slot, bool moved, bool exact) {
  const ShadowCascade& now = shadow_cascades_[cascade];
  if (!exact && gpu_casters_->Kept(cascade, lod_view, now, moved)) return false;
  if (exact) {
    SelectCascadeCasters(lod_view, now, *terrain_);
    ApplyTerrainSlotChanges();
  }
  gpu_casters_->Record(cmd, cascade, lod_view, now, slot, moved || exact);
  return true;
}

// The marched per-pixel path takes the mesh passes' variant for a high sun where the sun is high
// over every point within the farthest surface's distance (sun_high_variant.h): at noon on
// lavapipe the frame took 3.6 instead of 5.2 s. The other modes march nothing in these passes.
const MeshPipelines& Renderer::MeshPipelinesFor(const Scene& scene) {
  const double reach_m = glm::length(scene.camera.position) + scene_radius_m_;
  mesh_sun_high_used_ = options_.mode == AerialMode::kPerPixel && options_.sun_high_variants &&
                        SunHighWithin(frame_uniforms_, reach_m, tables_.atmosphere().bottom_radius_m);
  if (!mesh_sun_high_used_) return mesh_;
  if (!mesh_sun_high_) mesh_sun_high_ = MakeMeshPipelines(tables_.context(), options_, true);
  return *mesh_sun_high_;
}

// The sky's correction of the Earth's shadow (the marched per-pixel path's sky pass, the froxel
// mode's sky-view lattice) takes its variant for a high sun where every sun that it marches is
// high over every point of every sky ray (sun_high_variant.h, SunHighOverEverySkyRay): with the
// default tables at noon, not with the small ones, whose mu_s texel below the read's pair holds a
// sun 9.8 degrees up. The table-difference mode marches nothing.
bool Renderer::SkySunHighThisFrame() const {
  return options_.mode != AerialMode::kTableDifference && options_.sun_high_variants &&
         SunHighOverEverySkyRay(frame_uniforms_, tables_.atmosphere(), tables_.options().resolution.scattering_mu_s);
}

const vk::GraphicsPipeline& Renderer::SkyPipelineFor() {
  if (!sky_sun_high_used_ || options_.mode != AerialMode::kPerPixel) return sky_;
  if (!sky_sun_high_) sky_sun_high_.emplace(tables_.context(), SkyPipeline(options_.mode, true));
  return *sky_sun_high_;
}

const vk::ComputePipeline& Renderer::SkyViewCorrectionPipelineFor() {
  if (!sky_sun_high_used_) return sky_view_correction_;
  if (!sky_view_correction_sun_high_) sky_view_correction_sun_high_ = SkyViewCorrectionPipeline(tables_.context(), true);
  return *sky_view_correction_sun_high_;
}

std::vector<vk::Slot> Renderer::MeshSlots(uint32_t slot) const {
  return {vk::UniformBufferSlot{&tables_.uniform_buffer()}, vk::UniformBufferSlot{&frame_buffers_[slot]},
          tables_.Sampled(tables_.transmittance()), tables_.Sampled(tables_.irradiance()),
          tables_.Sampled(tables_.multiple_density()), tables_.Sampled(froxels_.rayleigh()),
          tables_.Sampled(froxels_.mie()), tables_.Sampled(froxels_.transmittance()),
          vk::UniformBufferSlot{&shadow_buffers_[slot]}, shadow_map_.slot(), tables_.Sampled(sun_visibility_),
          tables_.Sampled(tables_.rayleigh()), tables_.Sampled(tables_.mie()), tables_.Sampled(tables_.multiple())};
}

const vk::GraphicsPipeline& OpaquePipelines::For(SunVisibilitySource source) const {
  switch (source) {
    case SunVisibilitySource::kLookUpAndCache: return *look_up_and_cache;
    case SunVisibilitySource::kCache: return *cache;
    case SunVisibilitySource::kLookUp: break;
  }
  return look_up;
}

// Which meshes and chunks read the froxels per pixel (surface_reads.h), by their longest edge at
// the nearest point of their bounds.
void Renderer::ChooseFroxelReads(const Camera& camera) {
  const AirScales air = MakeAirScales(tables_.atmosphere());
  auto per_pixel = [&](double edge_m, double rise_m, double distance_m) {
    return options_.surface_froxel_reads == SurfaceFroxelReads::kPerPixel ||
           (options_.surface_froxel_reads == SurfaceFroxelReads::kPerVertexWhereThin &&
            ReadsFroxelsPerPixel(options_.froxels, air, edge_m, rise_m, distance_m));
  };
  mesh_reads_per_pixel_.clear();
  for (const MeshDraw& draw : geometry_.opaque_draws())
    mesh_reads_per_pixel_.push_back(
        per_pixel(draw.longest_edge_m, draw.largest_rise_m, glm::length(draw.center - camera.position) - draw.radius_m));
  auto first_per_vertex = std::stable_partition(
      terrain_chunks_.begin(), terrain_chunks_.end(), [&](const terrain::SelectedChunk& chunk) {
        const terrain::ChunkInfo* info = terrain_->Find(chunk.id);
        return per_pixel(info->longest_edge_m, info->largest_rise_m,
                         terrain::DistanceToBounds(camera.position, info->bounds));
      });
  terrain_per_pixel_ = size_t(first_per_vertex - terrain_chunks_.begin());
}

void Renderer::BeginOpaqueCommands(vk::IndirectDraws& commands) const {
  commands.Begin(geometry_.opaque_draws().size() + terrain_chunks_.size());
}

// The opaque meshes and terrain chunks whose froxel reads are pixel_reads (per pixel or per vertex),
// or all of them, with one pipeline: an indirect draw for the meshes with back faces culled, one
// for the double-sided ones and one for the terrain's chunks, whatever their number.
RecordedDraws Renderer::DrawOpaqueRun(const vk::CommandBuffer& cmd, const vk::GraphicsPipeline& pipeline,
                                      const std::vector<vk::Slot>& slots, std::optional<bool> pixel_reads,
                                      vk::IndirectDraws& commands) const {
  RecordedDraws recorded{.binds = 1};
  pipeline.Bind(cmd, slots);
  vk::BindMesh(cmd, geometry_.opaque_vertices(), geometry_.opaque_indices());
  const std::vector<MeshDraw>& draws = geometry_.opaque_draws();
  for (bool double_sided : {false, true}) {
    for (size_t i = 0; i < draws.size(); ++i) {
      if (draws[i].double_sided != double_sided) continue;
      if (pixel_reads && bool(mesh_reads_per_pixel_[i]) != *pixel_reads) continue;
      commands.Add(draws[i].index_count, draws[i].first_index, 0, draws[i].ground ? kGroundDetailInstance : 0);
    }
    vk::SetCullMode(cmd, double_sided ? ::vk::CullModeFlagBits::eNone : ::vk::CullModeFlagBits::eBack);
    recorded.draws += commands.Draw(cmd);
  }
  if (gpu_terrain_ && options_.passes.terrain) {
    vk::SetCullMode(cmd, ::vk::CullModeFlagBits::eBack);
    vk::BindMesh(cmd, terrain_->vertices(), terrain_->indices());
    recorded.draws += gpu_terrain_->Draw(cmd, pixel_reads);
    return recorded;
  }
  if (terrain_chunks_.empty()) return recorded;
  vk::SetCullMode(cmd, ::vk::CullModeFlagBits::eBack);
  vk::BindMesh(cmd, terrain_->vertices(), terrain_->indices());
  const size_t first = pixel_reads.value_or(true) ? 0 : terrain_per_pixel_;
  const size_t end = pixel_reads.value_or(false) ? terrain_per_pixel_ : terrain_chunks_.size();
  for (size_t i = first; i < end; ++i) {
    terrain::IndexRange range = terrain::ChunkIndexRange(terrain_chunks_[i].skirts);
    commands.Add(range.count, range.first, terrain_->VertexOffset(terrain_chunks_[i].id), kGroundDetailInstance);
  }
  recorded.draws += commands.Draw(cmd);
  return recorded;
}

// Nearest first, so that early depth tests skip the shading of what is hidden: the scene's meshes
// (landmarks and models standing on the ground), then the terrain's chunks by distance; those
// that read the froxels per pixel before those that read them per vertex.
RecordedDraws Renderer::DrawOpaque(const vk::CommandBuffer& cmd, const MeshPipelines& pipelines,
                                   SunVisibilitySource source, const std::vector<vk::Slot>& slots,
                                   vk::IndirectDraws& commands) const {
  BeginOpaqueCommands(commands);
  if (!pipelines.per_vertex)
    return DrawOpaqueRun(cmd, pipelines.per_pixel.For(source), slots, std::nullopt, commands);
  RecordedDraws recorded = DrawOpaqueRun(cmd, pipelines.per_pixel.For(source), slots, true, commands);
  recorded += DrawOpaqueRun(cmd, pipelines.per_vertex->For(source), slots, false, commands);
  return recorded;
}

// With the aerial perspective applied in a full-screen pass: that pass, where the opaque pass drew,
// after it and inside the frame's Rendering scope of the radiance.
RecordedDraws Renderer::DrawComposite(const vk::CommandBuffer& cmd, uint32_t slot, const vk::GraphicsPipeline& composite,
                                      std::vector<vk::Slot> mesh_slots) const {
  vk::GpuTimer& timer = *timers_[slot];
  timer.Begin(cmd, "aerial composite");
  mesh_slots.push_back(tables_.Sampled(surface_radiance_));
  composite.Bind(cmd, mesh_slots);
  vk::DrawGeneratedTriangle(cmd);
  timer.End(cmd);
  return {.draws = 1, .binds = 1};
}

// The sky where no geometry was drawn, then the transparent objects over everything, inside the
// frame's Rendering scope.
RecordedDraws Renderer::DrawSkyAndTransparent(const vk::CommandBuffer& cmd, uint32_t slot,
                                              const vk::GraphicsPipeline& sky, const vk::GraphicsPipeline& transparent,
                                              const std::vector<vk::Slot>& mesh_slots) const {
  RecordedDraws recorded;
  vk::GpuTimer& timer = *timers_[slot];
  timer.Begin(cmd, "sky");
  if (options_.passes.sky) {
    sky.Bind(cmd, {vk::UniformBufferSlot{&tables_.uniform_buffer()}, vk::UniformBufferSlot{&frame_buffers_[slot]},
                   tables_.Sampled(tables_.transmittance()), tables_.Sampled(tables_.rayleigh()),
                   tables_.Sampled(tables_.mie()), tables_.Sampled(tables_.multiple()),
                   tables_.Sampled(tables_.irradiance()), tables_.Sampled(sky_rayleigh_),
                    tables_.Sampled(sky_mie_), tables_.Sampled(sky_background_)});
    vk::DrawGeneratedTriangle(cmd);
    recorded += {.draws = 1, .binds = 1};
    if (sun_disc_) {
      sun_disc_->Bind(cmd, {vk::UniformBufferSlot{&tables_.uniform_buffer()}, vk::UniformBufferSlot{&frame_buffers_[slot]},
                            tables_.Sampled(sky_background_)});
      vk::DrawGeneratedTriangle(cmd);
      recorded += {.draws = 1, .binds = 1};
    }
  }
  timer.End(cmd);
  timer.Begin(cmd, "transparent raster");
  if (options_.passes.transparent && geometry_.transparent_index_count() > 0) {
    transparent.Bind(cmd, mesh_slots);
    vk::BindMesh(cmd, geometry_.transparent_vertices(), geometry_.transparent_indices(slot));
    vk::DrawIndexed(cmd, geometry_.transparent_index_count());
    recorded += {.draws = 1, .binds = 1};
  }
  timer.End(cmd);
  return recorded;
}

void Renderer::Record(const vk::CommandBuffer& cmd, const Scene& scene, uint32_t slot,
                      bool complete) {
  if (slot >= options_.frames_in_flight)
    throw Error("frame slot", std::to_string(slot), "below " + std::to_string(options_.frames_in_flight));
  const vk::Buffer& frame = frame_buffers_[slot];
  vk::GpuTimer& timer = *timers_[slot];
  FrameUniforms uniforms = MakeFrameUniforms(scene, tables_.atmosphere().bottom_radius_m, options_.render_width(),
                                             options_.render_height(), options_.froxels);
  still_view_ = frames_recorded_ > 0 && SameFrame(uniforms, frame_uniforms_);
  frame_uniforms_ = uniforms;
  sky_sun_high_used_ = SkySunHighThisFrame();
  frame_buffers_[slot].Write(std::as_bytes(std::span(&frame_uniforms_, 1)));
  geometry_.SortTransparent(scene.camera.position, slot);
  frame_info_ = {};
  SelectTerrain(scene, complete, slot);
  ChooseFroxelReads(scene.camera);

  // The previous frame's reads and writes of the shared images come before this frame's.
  vk::FullBarrier(cmd);
  timer.Reset(cmd);
  RecordTerrainSelection(cmd, slot);
  timer.Begin(cmd, "shadow map");
  RecordShadowMap(cmd, scene, slot, complete || frames_recorded_ == 0);  // the first frame builds all it needs
  timer.End(cmd);
  ShadowUniforms shadow =
      MakeShadowUniforms(shadow_cascades_, scene.sun.Direction(), scene.camera, casters_, options_.shadows);
  shadow_buffers_[slot].Write(std::as_bytes(std::span(&shadow, 1)));
  if (options_.mode == AerialMode::kFroxel) {
    std::array<bool, kSkyViewLatticeBands> bands = SkyViewLatticeBandsToRemake(
        sky_view_lattice_keys_, MakeSkyViewKey(frame_uniforms_), complete, still_view_);
    bool lattice_remade = std::find(bands.begin(), bands.end(), true) != bands.end();
    if (lattice_remade) {
      timer.Begin(cmd, "sky view correction");
      RecordSkyViewCorrection(cmd, frame, bands);
      timer.End(cmd);
      vk::FullBarrier(cmd);
    }
    bool sky_view_stale = SkyViewStale(complete, lattice_remade);
    timer.Begin(cmd, "froxel build");
    if (!FroxelsReusable(froxels_key_, frame_uniforms_, frame_info_.shadow_map_updated)) {
      froxels_.Build(cmd, tables_, frame, shadow_buffers_[slot], shadow_map_.slot(),
                     options_.sun_high_variants
                         ? ChooseFroxelPassVariant(frame_uniforms_, tables_.atmosphere().bottom_radius_m)
                         : FroxelPassVariant::kGeneral);
      froxels_key_ = frame_uniforms_;
      frame_info_.froxels_updated = true;
    }
    timer.End(cmd);
    timer.Begin(cmd, "sky view");
    if (sky_view_stale) RecordSkyView(cmd, frame);
    timer.End(cmd);
    vk::FullBarrier(cmd);
  }
  std::vector<vk::Slot> mesh_slots = MeshSlots(slot);
  const MeshPipelines& pipelines = MeshPipelinesFor(scene);
  const vk::GraphicsPipeline& sky = SkyPipelineFor();
  // Every pixel is written once by the opaque pass or the sky, so the output is not cleared.
  vk::RenderTargets targets{.colors = {&output_}, .clear_colors = {std::nullopt}, .depth = &depth_, .clear_depth = 0.0f};
  const bool cacheable = pipelines.per_pixel.look_up_and_cache.has_value();
  RecordedDraws recorded;
  frame_info_.sun_visibility_cached =
      cacheable &&
      SunVisibilityReusable(sun_visibility_key_, frame_uniforms_, terrain_changes_, frame_info_.shadow_map_updated);
  const bool caching = !frame_info_.sun_visibility_cached && cacheable &&
                       SunVisibilityWorthCaching(frames_recorded_ == 0, still_view_);
  SunVisibilitySource source = SunVisibilitySource::kLookUp;
  if (caching) {
    sun_visibility_key_ = SunVisibilityKey{frame_uniforms_, terrain_changes_};
    source = SunVisibilitySource::kLookUpAndCache;
  } else if (frame_info_.sun_visibility_cached) {
    source = SunVisibilitySource::kCache;
  }
  // The opaque pass draws in a scope of its own where it writes more than the radiance (the sun
  // visibility) or something else (the surfaces' radiance that the aerial perspective's full-screen
  // pass reads in the next scope); the sky and the transparent objects draw into the radiance alone.
  if (caching || pipelines.composite) {
    {
      vk::RenderTargets opaque = targets;
      if (pipelines.composite) opaque.colors = {&surface_radiance_};  // only covered pixels are ever read
      if (caching) {
        opaque.colors.push_back(&sun_visibility_);
        opaque.clear_colors.push_back(std::nullopt);  // the same
      }
      vk::Rendering rendering(cmd, opaque);
      timer.Begin(cmd, "opaque raster");
      recorded += DrawOpaque(cmd, pipelines, source, mesh_slots, opaque_commands_[slot]);
      timer.End(cmd);
    }
    vk::FullBarrier(cmd);
    targets.clear_depth = std::nullopt;
    vk::Rendering rendering(cmd, targets);
    if (pipelines.composite) recorded += DrawComposite(cmd, slot, *pipelines.composite, mesh_slots);
    recorded += DrawSkyAndTransparent(cmd, slot, sky, pipelines.transparent, mesh_slots);
  } else {
    vk::Rendering rendering(cmd, targets);
    timer.Begin(cmd, "opaque raster");
    recorded += DrawOpaque(cmd, pipelines, source, mesh_slots, opaque_commands_[slot]);
    timer.End(cmd);
    recorded += DrawSkyAndTransparent(cmd, slot, sky, pipelines.transparent, mesh_slots);
  }
  frame_info_.draws += recorded.draws;
  frame_info_.draw_binds += recorded.binds;
  vk::FullBarrier(cmd);
  const bool shadowed_terrain = options_.shadows && terrain_ && options_.passes.terrain;
  const bool lattice_caught_up = options_.mode != AerialMode::kFroxel ||
                                 SkyViewLatticeCaughtUp(sky_view_lattice_keys_, MakeSkyViewKey(frame_uniforms_));
  const bool shadows_caught_up = !options_.shadows || ShadowTilesCaughtUp(shadow_cascades_, scene.sun.Direction());
  frame_info_.settled = frame_info_.deferred == 0 && !terrain_feedback_pending_ && (!shadowed_terrain || shadow_selection_whole_) &&
                        lattice_caught_up && shadows_caught_up;
  ++frames_recorded_;
  last_slot_ = slot;
}

std::vector<vk::PassTime> Renderer::PassTimes(uint32_t slot) const { return timers_[slot]->Collect(); }

std::vector<vk::PassTime> Renderer::Render(const Scene& scene, bool complete) {
  tables_.context().Submit([&](const vk::CommandBuffer& cmd) { Record(cmd, scene, 0, complete); });
  return PassTimes(0);
}

ImageRgbF Renderer::ReadOutput() const {
  ImageRgbF rendered{options_.render_width(), options_.render_height(),
                     vk::ReadImageFloats(tables_.context(), output_)};
  if (rendered.width == options_.width && rendered.height == options_.height) return rendered;
  return ResizeBilinear(rendered, options_.width, options_.height);
}

ImageRgbF Renderer::ReadSurface(SurfaceLight light) const {
  const vk::Context& context = tables_.context();
  std::optional<vk::GraphicsPipeline> sky_only;
  if (light == SurfaceLight::kSkyOnly)
    sky_only.emplace(context, MeshPipeline("frame/opaque.vert", "frame/surface.frag", false,
                                           MeshConstants(options_, {.light = SurfaceLight::kSkyOnly})));
  vk::Image surface(context, Target(options_, vk::kRgba32f));
  vk::Image depth(context, Target(options_, vk::kDepth32f));
  vk::IndirectDraws commands(context);
  BeginOpaqueCommands(commands);
  context.Submit([&](const vk::CommandBuffer& cmd) {
    surface.InitializeLayout(cmd);
    depth.InitializeLayout(cmd);
    {
      vk::Rendering rendering(cmd, {.colors = {&surface}, .clear_colors = {std::array<float, 4>{0, 0, 0, -1}},
                                    .depth = &depth, .clear_depth = 0.0f});
      DrawOpaqueRun(cmd, sky_only ? *sky_only : surface_, MeshSlots(last_slot_), std::nullopt, commands);
    }
    vk::FullBarrier(cmd);
  });
  return ImageRgbF{options_.render_width(), options_.render_height(), vk::ReadImageFloats(context, surface)};
}

}  // namespace aerial
