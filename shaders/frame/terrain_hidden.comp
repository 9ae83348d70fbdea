#version 450
#extension GL_GOOGLE_include_directive : require
// The chunks the walk kept that are not seen, whole or in part: a block of 2 x 2 cells is unseen
// when its ground lies outside the view (terrain_occluders.comp found it so), or is hidden: as a
// target, it rises no higher than the horizon (terrain_horizon.glsl) of the bands wholly in front of
// it, in every azimuth bin it spans, so that each of its rays passes under the ground first. A
// chunk whose every block is unseen is left out; of the others, the unseen blocks that come last in
// one of the block orders are left out of the chunk's draw, in the order that leaves out most
// (terrain::ChunkBlockIndexRange). Stage 0 first makes the horizon cumulative, so that each band
// holds what the nearer ones hold; stage 1 tests four chunks a workgroup, an invocation per block.
layout(local_size_x = 64) in;
layout(constant_id = 0) const int kStage = 0;

#include "terrain_horizon.glsl"
#include "terrain_keys.glsl"

// The selection's chunks: x their key (terrain_select.comp), y their slot and what this pass finds
// (terrain_keys.glsl).
layout(std430, set = 0, binding = 0) buffer SelectionKeys { uvec2 keys[]; };
// The selection's header: the number of chunks the walk kept (terrain_select.comp's draw_count).
layout(std430, set = 0, binding = 1) readonly buffer SelectionDraws { uint candidates; };
// terrain_occluders.comp's: per chunk the walk kept, per block, its highest tangent, its azimuth
// span (bins) and the last band wholly in front of it (-1: it cannot be hidden; kOutsideView).
layout(std430, set = 0, binding = 2) readonly buffer BlockTargets { vec4 targets[]; };
// Per band and azimuth bin, OrderedBits of the tangent below which rays are hidden.
layout(std430, set = 0, binding = 3) buffer TerrainHorizon { uint horizon[]; };

const uint kBlockOrders = 4u;

// Per chunk, a bit per block seen.
shared uint visible_blocks[kBlockChunksPerGroup];

// Where block (i, j) comes in a block order (terrain::BlockAtPosition's inverse): rows from the
// south or the north, columns from the west or the east.
uint PositionInOrder(uint order, uint i, uint j) {
  const uint last = kChunkBlocks - 1u;
  switch (order) {
    case 0u: return j * kChunkBlocks + i;
    case 1u: return (last - j) * kChunkBlocks + i;
    case 2u: return i * kChunkBlocks + j;
    default: return (last - i) * kChunkBlocks + j;
  }
}

// The chunk's key word with the most unseen blocks that come last in a block order left out.
uint LeaveOutUnseenBlocks(uint word, uint visible) {
  uint best_order = 0u, best_left_out = 0u;
  for (uint order = 0u; order < kBlockOrders; ++order) {
    uint last_seen = 0u;
    for (uint block = 0u; block < kBlocksPerChunk; ++block)
      if ((visible & (1u << block)) != 0u)
        last_seen = max(last_seen, PositionInOrder(order, block % kChunkBlocks, block / kChunkBlocks));
    const uint left_out = kBlocksPerChunk - 1u - last_seen;
    if (left_out > best_left_out) {
      best_order = order;
      best_left_out = left_out;
    }
  }
  return best_left_out == 0u ? word : WithBlocksLeftOut(word, best_order, best_left_out);
}

bool TargetUnseen(vec4 target) {
  if (target.w == kOutsideView) return true;
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
  const uint chunk = gl_LocalInvocationIndex / kBlocksPerChunk, block = gl_LocalInvocationIndex % kBlocksPerChunk;
  const uint index = gl_WorkGroupID.x * kBlockChunksPerGroup + chunk;
  const bool present = index < candidates;
  if (block == 0u) visible_blocks[chunk] = 0u;
  barrier();
  if (present && !TargetUnseen(targets[index * kBlocksPerChunk + block])) atomicOr(visible_blocks[chunk], 1u << block);
  barrier();
  if (!present || block != 0u) return;
  const uint visible = visible_blocks[chunk];
  keys[index].y = visible == 0u ? keys[index].y | kHidden : LeaveOutUnseenBlocks(keys[index].y, visible);
}
