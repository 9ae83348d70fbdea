#pragma once
// One frame's froxel volume as an OpenVDB file (`aerial export-vdb`). See docs/vdb.md for the
// file's layout, units and coordinate frame.
//
// The froxel pass runs in the real renderer (Renderer::Render on the scene, at the image size the
// frame is for: only its aspect reaches the froxels, through the projection) and the three froxel
// images are read back as computed, float32. In both layouts each active voxel holds the grids of
// volume_grids.h, read from the froxels at its center the way the shaders read them (trilinear,
// SampleFroxels in shaders/include/froxel.glsl), and a voxel whose center lies below the ground
// (ground.h) or beyond the froxels' far distance stays inactive:
//  - frustum space (default): W x H x D voxels over the camera's frustum with OpenVDB's
//    NonlinearFrustumMap, the froxels' own columns resampled to linear depth slices
//    (camera_frustum.h). Houdini places it where the camera saw it; Blender ignores the
//    perspective part of a transform.
//  - world space (--world-grid VOXEL_M): a regular grid in the scene frame, linear transform;
//    voxels outside the frustum stay inactive. It lands in place in Blender and Houdini.
#include <cstdint>
#include <filesystem>
#include <string>

#include "aerial/atmosphere.h"
#include "aerial/export/vdb_file.h"
#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/render/frame_uniforms.h"
#include "aerial/render/renderer.h"
#include "froxel/froxel_placement.h"

namespace aerial {

// The image the froxels are computed for (`render`'s default size).
struct CaptureSize {
  int width = 1280;
  int height = 720;
  double aspect() const { return double(width) / height; }
};
// The world grid's bounding box may hold at most this many voxels (2^24: about 0.7 GB at peak).
inline constexpr int64_t kMaxWorldGridVoxels = int64_t(1) << 24;

// One frame's froxels and what they were computed for.
struct FroxelFrame {
  FroxelTexels texels;    // as the GPU computed them
  FrameUniforms uniforms;  // the frame block the froxel pass read
  CaptureSize size;
  Camera camera;
  Sun sun;
  LutVariant lut = LutVariant::k4D;
  // The tables' atmosphere in their channels' terms (ShaderAtmosphere: linear sRGB coefficients
  // for spectral tables): the density grid's (fog_density.h).
  AtmosphereParameters atmosphere;
  uint64_t atmosphere_hash = 0;     // the tables' AtmosphereParameters::Hash(), the cache key's
  uint64_t table_options_hash = 0;  // PrecomputeOptions::Hash()
  ColourMode colour = ColourMode::kRgb;  // what the three channels hold (PrecomputeOptions::colour)
  int spectral_wavelengths = 0;          // PrecomputeOptions::spectral_wavelengths, when spectral
  bool terrain = false;             // the scene's built-in terrain: the ground (ground.h)

  FroxelPlacement placement() const { return FroxelPlacement(uniforms, texels.grid); }
};

// The frame uniforms of the capture, computed on the CPU (for checks before any GPU work).
FrameUniforms CaptureFrameUniforms(const Scene& scene, double planet_radius_m, const FroxelGrid& grid,
                                   CaptureSize size);

// The froxels of the renderer's last frame (in froxel mode), which drew `scene`.
FroxelFrame ReadFroxelFrame(const Renderer& renderer, const Scene& scene);

// Renders the scene once, with the sun's shadow map or without (RenderOptions::shadows: once
// the froxels take the sun's visibility into account, the volume carries the shadows), and reads
// its froxels back.
FroxelFrame CaptureFroxels(const AtmosphereTables& tables, const Scene& scene, const FroxelGrid& grid,
                           CaptureSize size, bool shadows = true);

// The .vdb extension (any case), an existing parent directory, and a file can be created there.
// Throws Error naming --out.
void CheckVdbOutputPath(const std::filesystem::path& path);

// Throws Error naming --world-grid unless voxel_m is in (0, far_m] and the voxels over the
// frustum's bounding box number at most kMaxWorldGridVoxels. Returns about how many of them the
// froxels cover (sampled), the most voxels the volume can hold.
int64_t CheckWorldGrid(double voxel_m, const FroxelPlacement& placement);

// The frustum-space layout and the world-space one (see above). The frustum layout throws Error
// naming camera.near_m unless the near plane is in (0, far) (camera_frustum.h).
VdbVolume MakeFrustumVolume(const FroxelFrame& frame);
VdbVolume MakeWorldSpaceVolume(const FroxelFrame& frame, double voxel_m);

}  // namespace aerial
