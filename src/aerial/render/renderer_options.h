#pragma once
// What aerial's own tools choose of a frame besides the public RenderOptions (aerial/renderer.h):
// the fixed terrain mesh the level of detail is measured against (`--terrain mesh`) and the passes
// a benchmark leaves out. A caller's frame is always the level of detail's, with every pass.
#include <optional>

#include "aerial/renderer.h"

namespace aerial {

// How the built-in terrain is drawn: chunks with a level of detail that follows the camera, or
// the fixed polar mesh around the origin (BuildTerrainMesh) that the level of detail is measured
// against.
enum class TerrainMode { kLod, kStaticMesh };

// Where the terrain's chunks, the frame's and the shadow casters', are selected
// (terrain/lod_selection.h's rule either way): on the CPU, which then records a command per chunk
// drawn, or on the GPU (gpu_chunk_selection.h, gpu_shadow_casters.h), which writes the draws
// itself; the CPU then builds what the GPU asked for, a frame or more later. kAuto: on the GPU,
// except on a CPU device (lavapipe), where its passes cost the frame more than they spare the
// CPU (docs/speed.md).
enum class TerrainSelector { kAuto, kCpu, kGpu };

// Passes a benchmark may leave out to measure what they cost (lavapipe's timestamps inside one
// raster pass do not bracket its draws): every frame has all of them.
struct FramePasses {
  bool sky = true, transparent = true, terrain = true;
};

// Where opaque surfaces read the froxel volume (froxel mode): per vertex, interpolated, on
// triangles thin in depth and per pixel on others (surface_reads.h), or, to compare with, per
// pixel everywhere, per vertex everywhere, or once per pixel in a full-screen pass after the
// opaque pass (deferred: aerial_composite.frag), which reads what per pixel everywhere reads.
enum class SurfaceFroxelReads { kPerVertexWhereThin, kPerPixel, kPerVertex, kFullScreenPass };

// Reads of the opaque fragments a benchmark leaves out to measure what each costs: the froxel
// volume's (a constant segment instead), the sun visibility's (1 instead), or every read and
// operation of their shading (a constant radiance instead: what is left of the opaque pass is its
// rasterization, its vertices and its depth tests). Every frame has all of them.
struct LeftOutReads {
  bool froxels = false, sun_visibility = false, shading = false;
};

// RendererOptions{{.width = 96, .height = 54}, TerrainMode::kStaticMesh}.
struct RendererOptions : RenderOptions {
  TerrainMode terrain = TerrainMode::kLod;
  TerrainSelector terrain_selector = TerrainSelector::kAuto;
  FramePasses passes;
  SurfaceFroxelReads surface_froxel_reads = SurfaceFroxelReads::kPerVertexWhereThin;
  LeftOutReads left_out_reads;
  // The froxel pass's and the marched opaque pass's variants for a high sun, where they compute
  // the same values (sun_high_variant.h); off: the general passes always, to compare with.
  bool sun_high_variants = true;
  // The terrain's fine albedo detail (shaders/include/ground_detail.glsl); off: its materials'
  // per-vertex albedo alone, to compare with.
  bool ground_detail = true;
  // A shadow tile whose window held and whose terrain casters changed is redrawn only where they
  // changed (shadow_tile_region.h); off: whole, to compare with.
  bool shadow_tile_regions = true;
  // The per-pixel modes' aerial perspective: once per pixel in a full-screen pass after the opaque
  // pass (deferred, aerial_composite.frag), or, to compare with, in the opaque fragments, which a
  // CPU rasterizer shades several times per covered pixel (a fragment for every 4x4 stamp that a
  // triangle touches, each marching the whole segment).
  bool per_pixel_in_full_screen_pass = true;
  // Terrain chunks built by any renderer of the process are kept for all (terrain/built_chunks.h);
  // off: this renderer builds its own, as aerial_bench_render's timed frames do, so that a
  // configuration measured after another pays for its chunks too (their CPU times are figures).
  bool share_built_terrain = true;
  // Where the chunks the GPU's terrain selections ask for are built: on other threads beside the
  // frame (true), as engines stream terrain, or on the rendering thread before it records (false).
  // Unset: beside the frame, except on a CPU device, whose frame runs on the cores the builders
  // would take (docs/speed.md).
  std::optional<bool> terrain_builds_in_background;
};

// Whether the opaque pass writes its surfaces' radiance and distance and a full-screen pass after
// it applies their aerial perspective: froxels read in that pass, or a per-pixel mode's there.
bool AerialPerspectiveInFullScreenPass(const RendererOptions& options);

// EstimateFrameMemory (aerial/renderer.h), without the terrain chunk slots for the fixed mesh and
// without the GPU's selection of them for TerrainSelector::kCpu. kAuto counts it: the estimate is
// made before a device is chosen.
FrameMemory EstimateFrameMemory(const RendererOptions& options);
// The device memory of the terrain's selection on the GPU (TerrainSelector::kGpu).
uint64_t GpuTerrainSelectionBytes(const RenderOptions& options);

// A SceneRenderer (aerial/renderer.h) with these options (src/aerial/api/scene_renderer.cpp).
SceneRenderer MakeSceneRenderer(const Tables& tables, const Scene& scene, const RendererOptions& options);

}  // namespace aerial
