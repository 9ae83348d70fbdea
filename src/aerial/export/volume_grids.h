#pragma once
// The grids every layout of export-vdb writes, one value each per active voxel, from the froxels
// read at the voxel's center (docs/vdb.md):
//   rayleigh_inscatter, mie_inscatter  Vec3S, W/m^2/nm, phase-free; background 0
//   transmittance                     Vec3S, from the camera; background 1, so that an inactive
//                                     voxel reads as clear air
//   inscatter_luminance               float, Rec. 709 luma of the inscatter; background 0
//   density                           float, 1/m, the extinction coefficient (fog_density.h);
//                                     background 0, grid class fog volume
// The inscatter grids and transmittance are not densities and keep the class unknown.
#include <cstddef>
#include <vector>

#include "aerial/export/vdb_file.h"
#include "froxel/froxel_placement.h"

namespace aerial {

class VolumeGrids {
 public:
  explicit VolumeGrids(size_t voxels);  // room for this many

  // One voxel's values: the froxels read at its center, and its density.
  void Add(const FroxelTexels::Sample& sample, double density);
  std::vector<VdbVolume::Grid> Take() &&;

 private:
  VdbVolume::Grid rayleigh_, mie_, transmittance_, luminance_, density_;
};

}  // namespace aerial
