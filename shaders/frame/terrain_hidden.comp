#version 450
#extension GL_GOOGLE_include_directive : require
// The chunks the walk kept that nearer terrain hides: those whose every block of 2 x 2 cells, as a
// target (terrain_occluders.comp), rises no higher than the horizon (terrain_horizon.glsl) of the
// bands wholly in front of it, in every azimuth bin it spans. Each of its rays then passes under
// the ground first. Stage 0 first makes the horizon cumulative, so that each band holds what the
// nearer ones hold; stage 1 tests four chunks a workgroup, an invocation per block.
layout(local_size_x = 64) in;
layout(constant_id = 0) const int kStage = 0;

#include "terrain_horizon.glsl"

// The selection's chunks: x their key (terrain_select.comp), y their slot.
layout(std430, set = 0, binding = 0) buffer SelectionKeys { uvec2 keys[]; };
// The selection's header: the number of chunks the walk kept (terrain_select.comp's draw_count).
layout(std430, set = 0, binding = 1) readonly buffer SelectionDraws { uint candidates; };
// terrain_occluders.comp's: per chunk the walk kept, per block, its highest tangent, its azimuth
// span (bins) and the last band wholly in front of it (-1: it cannot be hidden).
layout(std430, set = 0, binding = 2) readonly buffer BlockTargets { vec4 targets[]; };
// Per band and azimuth bin, OrderedBits of the tangent below which rays are hidden.
layout(std430, set = 0, binding = 3) buffer TerrainHorizon { uint horizon[]; };

const uint kBlocksPerChunk = 16u, kChunksPerGroup = 4u;  // terrain_occluders.comp's
const uint kHidden = 0x80000000u;                        // terrain_select.comp's, on the slot

shared bool visible[kChunksPerGroup];

bool TargetHidden(vec4 target) {
  const int band = int(target.w);
  if (band < 0) return false;
  for (int bin = int(floor(target.y)); bin <= int(floor(target.z)); ++bin) {
    uint known = horizon[HorizonIndex(band, bin)];
    if (known == 0u || target.x >= FromOrderedBits(known)) return false;
  }
  return true;
}

void main() {
  if (kStage == 0) {
    const int bin = int(gl_GlobalInvocationID.x);
    uint known = horizon[bin];
    for (int band = 1; band < kHorizonBands; ++band) {
      known = max(known, horizon[HorizonIndex(band, bin)]);
      horizon[HorizonIndex(band, bin)] = known;
    }
    return;
  }
  const uint chunk = gl_LocalInvocationIndex / kBlocksPerChunk;
  const uint index = gl_WorkGroupID.x * kChunksPerGroup + chunk;
  const bool present = index < candidates;
  if (gl_LocalInvocationIndex % kBlocksPerChunk == 0u) visible[chunk] = false;
  barrier();
  if (present && !TargetHidden(targets[index * kBlocksPerChunk + gl_LocalInvocationIndex % kBlocksPerChunk]))
    visible[chunk] = true;
  barrier();
  if (present && gl_LocalInvocationIndex % kBlocksPerChunk == 0u && !visible[chunk]) keys[index].y |= kHidden;
}
