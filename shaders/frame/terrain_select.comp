#version 450
// The terrain's level-of-detail selection (src/aerial/terrain/lod_selection.h) made by the GPU, so
// that the CPU records a fixed number of draws whatever the terrain shows (render/gpu_chunk_selection.h).
// One workgroup walks the tree of built chunks a level at a time, as SelectChunks does: a chunk
// outside the frustum is left (unless a finer one below it may rise into it), a chunk whose
// geometric error projects to more than the bound is replaced by its children once all of them
// that may be in the frustum are built, and is drawn in their place (and asks for them) until
// then. The chunks drawn are then sorted front to back in quadtree order from the camera, each
// given the skirts of the sides whose neighbour is not drawn at its level, and written as indexed
// indirect draws.
layout(local_size_x = 256) in;

const int kNotBuilt = -1;
const int kOutsideTerrain = -2;  // a child beyond the terrain's radius: never drawn
const int kMaxChunkLevel = 13;
const float kRootSizeM = 204800.0;
// A point h above sea level sits at (R + h) / R times its sea-level x and y, so a chunk's bounds
// spread past its sea-level footprint by a little (lod_selection.cpp's kHorizontalSpread).
const float kHorizontalSpread = 2e-3;
const uint kWorkgroupSize = 256;

struct ChunkNode {
  vec4 lower;         // the bounds' lower corner in the scene frame (m); w: geometric error (m)
  vec4 upper;         // the bounds' upper corner
  ivec4 children;     // slots of the four children in terrain::Children order
  ivec4 neighbours;   // slots of the chunks of its level across its south, east, north, west sides
  ivec4 id;           // level, x, y
};
layout(std430, set = 0, binding = 0) readonly buffer ChunkTree { ChunkNode nodes[]; };

layout(std140, set = 0, binding = 1) uniform SelectionView {
  vec4 planes[5];             // the frustum's sides and near plane (terrain::LodView::planes)
  vec4 camera;                // xyz: position; w: pixels per radian
  vec4 limits;                // x: error bound (px); y: resolved error (m); zw: the camera's sea-level x, y
  ivec4 root;                 // x: the root's slot or kNotBuilt; y: generation; z: vertices per slot; w: first instance
  uvec4 index_ranges[16];     // per skirt mask (terrain::ChunkIndexRange): first index, index count
};

// Two queues of slots, a level's and the next's, each as long as there are slots.
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
layout(std430, set = 0, binding = 5) writeonly buffer SelectionDraws {
  uint draw_count;
  uint deferred;         // chunks drawn, or left, in place of children not built yet
  uint requested;        // entries of SelectionRequests written
  DrawCommand draws[];
};
// The children a refinement needs that are not built (level, x, y), for the CPU to build.
layout(std430, set = 0, binding = 6) writeonly buffer SelectionRequests { ivec4 requests[]; };

shared uint queue_size[2];
shared uint draw_size, deferred_size, request_size;

bool IntersectsFrustum(vec3 lower, vec3 upper) {
  for (int i = 0; i < 5; ++i) {
    // The box's corner furthest along the plane's normal.
    vec3 corner = mix(lower, upper, greaterThanEqual(planes[i].xyz, vec3(0.0)));
    if (dot(planes[i].xyz, corner) + planes[i].w < 0.0) return false;
  }
  return true;
}

// Ulrich's test: the geometric error seen from the bounds' nearest point spans more pixels than
// the bound (inside the bounds, any error does).
bool TooCoarse(ChunkNode node) {
  vec3 p = camera.xyz;
  float distance = length(p - clamp(p, node.lower.xyz, node.upper.xyz));
  return node.lower.w * camera.w > limits.x * distance;
}

float ChunkSize(int level) { return kRootSizeM / float(1 << level); }

// Where a child that is not built may lie: its footprint, widened for the spread, over its
// parent's heights grown by the parent's error (EstimateChildBounds in lod_selection.cpp).
bool ChildMayBeInFrustum(ivec3 child, ChunkNode parent) {
  float size = ChunkSize(child.x);
  vec2 lower = -0.5 * kRootSizeM + vec2(child.yz) * size, upper = lower + size;
  vec2 margin = kHorizontalSpread * max(abs(lower), abs(upper)) + 1.0;
  return IntersectsFrustum(vec3(lower - margin, parent.lower.z - parent.lower.w),
                           vec3(upper + margin, parent.upper.z + parent.lower.w));
}

// The chunk's path from the root as ranks from the camera (2 bits a level, the child on the
// camera's side of both splitting lines first), packed from the top bit down: sorting by it
// sorts front to back (SortFrontToBack in lod_selection.cpp).
uint FrontToBackKey(ivec3 id) {
  uint key = 0u;
  for (int level = 0; level < id.x; ++level) {
    int shift = id.x - level - 1;
    ivec2 node = ivec2(id.y, id.z) >> (shift + 1);
    vec2 middle = -0.5 * kRootSizeM + (vec2(node) + 0.5) * ChunkSize(level);
    bvec2 camera_side = greaterThanEqual(limits.zw, middle);
    ivec2 child = (ivec2(id.y, id.z) >> shift) & 1;
    uint rank = (child.x != int(camera_side.x) ? 1u : 0u) + (child.y != int(camera_side.y) ? 2u : 0u);
    key |= rank << (30 - 2 * level);
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
  if (error <= limits.y || node.id.x == kMaxChunkLevel || !TooCoarse(node)) {
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
      for (uint i = t; i < n; i += kWorkgroupSize) {
        uint l = i ^ j;
        if (l <= i) continue;
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

void main() {
  const uint t = gl_LocalInvocationIndex;
  if (t == 0u) {
    queue_size[0] = 0u;
    queue_size[1] = 0u;
    draw_size = 0u;
    deferred_size = 0u;
    request_size = 0u;
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

  const uint drawn = draw_size;
  for (uint i = t; i < drawn; i += kWorkgroupSize) stamps[keys[i].y] = uint(root.y);
  uint n = 1u;
  while (n < drawn) n <<= 1u;
  for (uint i = drawn + t; i < n; i += kWorkgroupSize) keys[i] = uvec2(0xffffffffu);
  Synchronize();
  SortKeys(n, t);

  for (uint i = t; i < drawn; i += kWorkgroupSize) {
    int slot = int(keys[i].y);
    uvec4 range = index_ranges[SkirtMask(slot)];
    draws[i] = DrawCommand(range.y, 1u, range.x, slot * root.z, uint(root.w));
  }
  if (t == 0u) {
    draw_count = drawn;
    deferred = deferred_size;
    // Children asked for beyond the list's length are asked for again by a later selection.
    requested = min(request_size, uint(requests.length()));
  }
}
