#pragma once
// The grids every layout of export-vdb writes, one value each per active voxel, from the froxels
// read at the voxel's center (docs/vdb.md):
//   rayleigh_inscatter, mie_inscatter  Vec3S, W/m^2/nm, phase-free; background 0
//   transmittance                     Vec3S, from the camera; background 1, so that an inactive
//                                     voxel reads as clear air
//   inscatter_luminance               float, Rec. 709 luma of the inscatter; background 0
//   density                           float, 1/m, the extinction coefficient (fog_density.h);
//                                     background 0, grid class fog volume
//   scattering, absorption            Vec3S, 1/m per channel, the air's own coefficients at the
//                                     voxel (AirCoefficientsAt): what a path tracer renders in colour,
//                                     seen from anywhere; background 0
// The inscatter grids and transmittance hold what the camera sees and are valid from the export's
// camera only; they, scattering and absorption keep the class unknown.
#include <cstddef>
#include <vector>

#include "aerial/export/fog_density.h"
#include "aerial/export/vdb_file.h"
#include "froxel/froxel_placement.h"

namespace aerial {

class VolumeGrids {
 public:
  explicit VolumeGrids(size_t voxels);  // room for this many

  // One voxel's values: the froxels read at its center, and the air's coefficients there.
  void Add(const FroxelTexels::Sample& sample, const AirCoefficients& air);
  std::vector<VdbVolume::Grid> Take() &&;

 private:
  VdbVolume::Grid rayleigh_, mie_, transmittance_, luminance_, density_, scattering_, absorption_;
};

}  // namespace aerial
