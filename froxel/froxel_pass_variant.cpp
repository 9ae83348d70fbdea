#include "froxel/froxel_pass_variant.h"

namespace aerial {

bool SunHighAtEveryFroxel(const FrameUniforms& frame, double bottom_radius_m) {
  return SunHighWithin(frame, double(frame.froxel_depth[0]), bottom_radius_m);
}

FroxelPassVariant ChooseFroxelPassVariant(const FrameUniforms& frame, double bottom_radius_m) {
  return SunHighAtEveryFroxel(frame, bottom_radius_m) ? FroxelPassVariant::kSunHigh : FroxelPassVariant::kGeneral;
}

}  // namespace aerial
