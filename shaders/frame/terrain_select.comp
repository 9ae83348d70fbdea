#version 450
#extension GL_GOOGLE_include_directive : require
// The terrain's level-of-detail selection (src/aerial/terrain/lod_selection.h) made by the GPU, so
// that the CPU records a fixed number of draws whatever the terrain shows (render/gpu_chunk_selection.h).
// One workgroup walks the tree of built chunks a level at a time, as SelectChunks does: a chunk
// outside the frustum is left (unless a finer one below it may rise into it), a chunk whose
// geometric error projects to more than the bound is replaced by its children once all of them
// that may be in the frustum are built, and is drawn in their place (and asks for them) until
// then. The chunks drawn are then sorted front to back in quadtree order from the camera, each
// given the skirts of the sides whose neighbour is not drawn at its level, and written as indexed
// indirect draws. Before the sort, the chunks that nearer terrain hides are left out: those that
// terrain_hidden.comp marked, against the horizon terrain_occluders.comp built from the chunks the
// walk kept (terrain_horizon.glsl); a chunk it found hidden in part draws without the hidden blocks
// that come last in a block order (terrain_keys.glsl).
// One workgroup, of kWorkgroupSize invocations (render/gpu_chunk_selection.cpp chooses it).
layout(local_size_x_id = 1) in;
// 0: the walk, which leaves the chunks it would draw in SelectionKeys; 1: after the horizon's passes,
// the rest: those hidden left out, the sort, the draws.
layout(constant_id = 0) const int kStage = 0;

#include "terrain_selection.glsl"
#include "terrain_keys.glsl"

const uint kWorkgroupSize = gl_WorkGroupSize.x;

// Two queues of slots, a level's and the next's, each as long as there are slots; after the walk,
// the chunks drawn as pairs of key and slot.
layout(std430, set = 0, binding = 2) coherent buffer SelectionQueues { int queue[]; };
// Per slot, the generation of the last selection that drew it.
layout(std430, set = 0, binding = 3) coherent buffer SelectionStamps { uint stamps[]; };
// Per drawn chunk before the sort: its quadtree key and slot; a power of two at least the slots.
layout(std430, set = 0, binding = 4) coherent buffer SelectionKeys { uvec2 keys[]; };

struct DrawCommand {  // VkDrawIndexedIndirectCommand
  uint index_count, instance_count, first_index;
  int vertex_offset;
  uint first_instance;
};
// Two lists of draws, each front to back: the chunks that read the froxels per pixel, and those
// that read them per vertex (render/surface_reads.h), from draws[0] and draws[stamps.length()].
layout(std430, set = 0, binding = 5) coherent buffer SelectionDraws {
  uint draw_count;       // per pixel; after the walk: all the chunks it would draw
  uint deferred;         // chunks drawn, or left, in place of children not built yet
  uint requested;        // entries of SelectionRequests written
  uint hidden;           // chunks left out because nearer terrain hides them
  uint per_vertex_count;
  uint indices;          // of every chunk drawn, skirts included
  // How far the camera may move before a refinement test could come out otherwise (m, as float
  // bits: terrain::Selection::camera_slack_m).
  uint camera_slack;
  // 1 where the chunks drawn (their slots, fills and skirts) differ from the last selection's
  // (SelectionView::compare), else 0: a condition for the draws of an image that keeps what it drew.
  uint changed;
  DrawCommand draws[];
};
// The children a refinement needs that are not built (level, x, y), for the CPU to build.
layout(std430, set = 0, binding = 6) writeonly buffer SelectionRequests { ivec4 requests[]; };
// The dispatch of the horizon's passes over chunks (terrain_occluders.comp, terrain_hidden.comp): a
// workgroup per kBlockChunksPerGroup chunks the walk would draw (VkDispatchIndirectCommand).
layout(std430, set = 0, binding = 7) writeonly buffer BlockDispatch { uvec3 block_groups; };
// Per slot, what the last comparing selection drew there: its fill and 1 + its skirt mask; 0 if none.
layout(std430, set = 0, binding = 8) buffer TileContent { uvec2 content[]; };

shared uint queue_size[2];
shared uint draw_size, deferred_size, request_size, drawn_size, per_vertex_size, index_size, slack_bits, changed_size;
const uint kReadsPerVertex = 0x80000000u;  // the sort key's top bit

// The camera's distance to the chunk's bounds (0 inside them).
float DistanceToBounds(ChunkNode node) {
  return length(camera.xyz - clamp(camera.xyz, node.lower.xyz, node.upper.xyz));
}

// Ulrich's test: the geometric error seen from the bounds' nearest point spans more pixels than
// the bound (inside the bounds, any error does).
bool TooCoarse(ChunkNode node) { return node.lower.w * camera.w > limits.x * DistanceToBounds(node); }

// How far the camera may move before TooCoarse could change its answer (RefinementSlackM): the
// distance from the bounds at which the error projects to the bound is error * pixels per radian
// / bound.
float RefinementSlack(ChunkNode node) {
  return abs(DistanceToBounds(node) - node.lower.w * camera.w / limits.x);
}

// Where a child that is not built may lie: its footprint, widened for the spread, over its
// parent's heights grown by the parent's error (EstimateChildBounds in lod_selection.cpp).
bool ChildMayBeInFrustum(ivec3 child, ChunkNode parent) {
  const float size = ChunkSize(child.x);
  const vec2 lower = -0.5 * kRootSizeM + vec2(child.yz) * size;
  return FootprintMayBeInFrustum(lower, lower + size, parent.lower.z - parent.lower.w, parent.upper.z + parent.lower.w);
}

// The chunk's path from the root as ranks from the camera (2 bits a level, the child on the
// camera's side of both splitting lines first), packed from the second bit down: sorting by it
// sorts front to back (SortFrontToBack in lod_selection.cpp). The top bit is left for the reads.
uint FrontToBackKey(ivec3 id) {
  uint key = 0u;
  for (int level = 0; level < id.x; ++level) {
    int shift = id.x - level - 1;
    ivec2 node = ivec2(id.y, id.z) >> (shift + 1);
    vec2 middle = -0.5 * kRootSizeM + (vec2(node) + 0.5) * ChunkSize(level);
    bvec2 camera_side = greaterThanEqual(limits.zw, middle);
    ivec2 child = (ivec2(id.y, id.z) >> shift) & 1;
    uint rank = (child.x != int(camera_side.x) ? 1u : 0u) + (child.y != int(camera_side.y) ? 2u : 0u);
    key |= rank << (29 - 2 * level);
  }
  return key;
}

void Draw(int slot, ChunkNode node) {
  uint i = atomicAdd(draw_size, 1u);
  keys[i] = uvec2(FrontToBackKey(node.id.xyz), uint(slot));
}

void Request(ivec3 child) {
  uint i = atomicAdd(request_size, 1u);
  if (i < requests.length()) requests[i] = ivec4(child, 0);
}

void Visit(int slot, int next_queue) {
  ChunkNode node = nodes[slot];
  const float error = node.lower.w;
  const bool inside = IntersectsFrustum(node.lower.xyz, node.upper.xyz);
  // A chunk's descendants lie within its bounds grown by its error.
  if (!inside && !IntersectsFrustum(node.lower.xyz - error, node.upper.xyz + error)) return;
  if (error <= limits.y) {
    if (inside) Draw(slot, node);
    return;
  }
  // Non-negative floats order as their bits do.
  if (node.id.x < kMaxChunkLevel && error > 0.0) atomicMin(slack_bits, floatBitsToUint(RefinementSlack(node)));
  if (node.id.x == kMaxChunkLevel || !TooCoarse(node)) {
    if (inside) Draw(slot, node);
    return;
  }
  bool ready = true;
  for (int k = 0; k < 4; ++k) {
    if (node.children[k] != kNotBuilt) continue;
    ivec3 child = ivec3(node.id.x + 1, 2 * node.id.yz + ivec2(k & 1, k >> 1));
    if (ChildMayBeInFrustum(child, node)) {
      ready = false;
      Request(child);
    }
  }
  if (!ready) {
    if (inside) Draw(slot, node);
    atomicAdd(deferred_size, 1u);
    return;
  }
  for (int k = 0; k < 4; ++k) {
    if (node.children[k] < 0) continue;
    uint i = atomicAdd(queue_size[next_queue], 1u);
    queue[next_queue * stamps.length() + i] = node.children[k];
  }
}

void Synchronize() {
  memoryBarrierBuffer();
  memoryBarrierShared();
  barrier();
}

// Bitonic sort of keys[0, n), n a power of two, each compared pair swapped by one invocation.
void SortKeys(uint n, uint t) {
  for (uint k = 2u; k <= n; k <<= 1u) {
    for (uint j = k >> 1u; j > 0u; j >>= 1u) {
      for (uint pair = t; pair < n / 2u; pair += kWorkgroupSize) {
        // The pair's first key: its number with a 0 inserted at j's bit; the second has a 1 there.
        const uint low = pair & (j - 1u), i = ((pair - low) << 1u) | low, l = i | j;
        uvec2 a = keys[i], b = keys[l];
        if ((a.x > b.x) == ((i & k) == 0u)) {
          keys[i] = b;
          keys[l] = a;
        }
      }
      Synchronize();
    }
  }
}

// The sides whose neighbour at the chunk's level is not drawn (terrain::MarkSkirts).
uint SkirtMask(int slot) {
  uint mask = 0u;
  for (int side = 0; side < 4; ++side) {
    int neighbour = nodes[slot].neighbours[side];
    if (neighbour < 0 || stamps[neighbour] != uint(root.y)) mask |= 1u << side;
  }
  return mask;
}

void Walk(uint t) {
  if (t == 0u) {
    queue_size[0] = 0u;
    queue_size[1] = 0u;
    draw_size = 0u;
    deferred_size = 0u;
    request_size = 0u;
    slack_bits = 0x7f800000u;  // +infinity
    if (root.x == kNotBuilt) {
      Request(ivec3(0));
    } else {
      queue[0] = root.x;
      queue_size[0] = 1u;
    }
  }
  Synchronize();
  for (int level = 0; level <= kMaxChunkLevel; ++level) {
    const int current = level & 1, next = current ^ 1;
    const uint size = queue_size[current];
    for (uint i = t; i < size; i += kWorkgroupSize) Visit(queue[current * stamps.length() + i], next);
    Synchronize();
    if (t == 0u) queue_size[current] = 0u;
    Synchronize();
  }
  if (t == 0u) {
    draw_count = draw_size;
    deferred = deferred_size;
    hidden = 0u;
    // Children asked for beyond the list's length are asked for again by a later selection.
    requested = min(request_size, uint(requests.length()));
    camera_slack = slack_bits;
    block_groups = uvec3((draw_size + kBlockChunksPerGroup - 1u) / kBlockChunksPerGroup, 1u, 1u);
  }
}

void Finish(uint t) {
  const uint candidates = draw_count;
  if (t == 0u) {
    drawn_size = 0u;
    per_vertex_size = 0u;
    index_size = 0u;
  }
  Synchronize();
  // The chunks drawn gather in the queues, free since the walk, in any order: they are sorted next,
  // and the sort's cost grows with the power of two it sorts. Those that read per vertex sort after
  // those that read per pixel: within its bounds' distance given by the CPU (PerPixelReadsWithinM).
  for (uint i = t; i < candidates; i += kWorkgroupSize) {
    uvec2 key = keys[i];
    if ((key.y & kHidden) != 0u) continue;
    ChunkNode node = nodes[SlotOfKey(key.y)];
    if (!(DistanceToBounds(node) < node.upper.w)) {
      key.x |= kReadsPerVertex;
      atomicAdd(per_vertex_size, 1u);
    }
    uint kept = atomicAdd(drawn_size, 1u);
    queue[2u * kept] = int(key.x);
    queue[2u * kept + 1u] = int(key.y);
  }
  Synchronize();
  const uint drawn = drawn_size, per_pixel = drawn - per_vertex_size;
  uint n = 1u;
  while (n < drawn) n <<= 1u;
  for (uint i = t; i < n; i += kWorkgroupSize)
    keys[i] = i < drawn ? uvec2(uint(queue[2u * i]), uint(queue[2u * i + 1u])) : uvec2(0xffffffffu);
  Synchronize();
  SortKeys(n, t);

  for (uint i = t; i < drawn; i += kWorkgroupSize) stamps[SlotOfKey(keys[i].y)] = uint(root.y);
  Synchronize();
  for (uint i = t; i < drawn; i += kWorkgroupSize) {
    const uint word = keys[i].y, left_out = BlocksLeftOutOfKey(word);
    const int slot = int(SlotOfKey(word));
    const uint skirts = SkirtMask(slot);
    // The whole list, or the one whose last blocks in the order found are left out.
    const uint first = left_out == 0u ? index_ranges[skirts].x : block_firsts[skirts][BlockOrderOfKey(word)];
    const uint count = index_ranges[skirts].y - left_out * kBlockIndices;
    draws[i < per_pixel ? i : stamps.length() + i - per_pixel] =
        DrawCommand(count, 1u, first, slot * root.z, uint(root.w));
    atomicAdd(index_size, count);
  }
  if (compare.x != 0u) {
    if (t == 0u) changed_size = compare.y;
    Synchronize();
    for (uint slot = t; slot < uint(stamps.length()); slot += kWorkgroupSize) {
      uvec2 drawn_here = stamps[slot] == uint(root.y) ? uvec2(nodes[slot].id.w, SkirtMask(int(slot)) + 1u) : uvec2(0u);
      if (content[slot] != drawn_here) {
        content[slot] = drawn_here;
        atomicOr(changed_size, 1u);
      }
    }
  }
  Synchronize();
  if (t == 0u) {
    changed = compare.x != 0u ? changed_size : 0u;
    draw_count = per_pixel;
    per_vertex_count = per_vertex_size;
    hidden = candidates - drawn;
    indices = index_size;
  }
}

void main() {
  if (kStage == 0)
    Walk(gl_LocalInvocationIndex);
  else
    Finish(gl_LocalInvocationIndex);
}
