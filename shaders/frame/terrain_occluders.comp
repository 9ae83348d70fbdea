#version 450
#extension GL_GOOGLE_include_directive : require
// Every chunk the selection may draw adds its ground to the horizon (terrain_horizon.glsl), four
// chunks a workgroup, and leaves what terrain_hidden.comp tests against it. A cell of the chunk's
// mesh never dips below its lowest vertex, so the shell at that height, lowered by a margin, lies
// under the ground across the cell: any ray under a point of it is hidden. A row of blocks of
// cells across the chunk is crossed by the vertical plane of every azimuth within its span, each
// plane through blocks that overlap the azimuth's bin, so the bin's tangent is the least of those
// blocks', known within the row's farthest distance; a block that spans the whole bin alone is
// crossed by every plane of it, and its own tangent holds there.
// Seen as a target, a block's mesh lies under its cells' highest vertex, so its rays rise no higher
// than that height over its nearest distance (or its farthest, when below the camera); and it lies
// within a box of its footprint and heights, which the frustum may leave out though the chunk's
// bounds, over all its heights, reach into it.
layout(local_size_x = 64) in;

#include "terrain_selection.glsl"
#include "terrain_horizon.glsl"
#include "terrain_keys.glsl"

// The selection's chunks (their slots in y).
layout(std430, set = 0, binding = 2) readonly buffer SelectionKeys { uvec2 keys[]; };
// The selection's header: the number of chunks the walk kept (terrain_select.comp's draw_count).
layout(std430, set = 0, binding = 3) readonly buffer SelectionDraws { uint candidates; };
// Per slot, per block of its chunk, its cells' lowest and highest heights (m):
// the mesh over the block lies between them (terrain::BlockHeights).
layout(std430, set = 0, binding = 4) readonly buffer ChunkBlockHeights { vec2 block_heights[]; };
// Per band and azimuth bin, OrderedBits of the tangent below which rays are hidden.
layout(std430, set = 0, binding = 5) coherent buffer TerrainHorizon { uint horizon[]; };
// Per chunk the walk kept, per block, the block as a target (terrain_hidden.comp): x: the highest
// tangent of its rays; y, z: its azimuth span (bins); w: the last band wholly in front of it, -1
// when it cannot be hidden, or kOutsideView.
layout(std430, set = 0, binding = 6) writeonly buffer BlockTargets { vec4 targets[]; };

// Occluders are blocks of 2 x 2 cells (terrain_keys.glsl): at a quarter of the work, they hide
// nearly as much.
const float kNoOccluder = -1e30;
// How far an occluder is lowered below its cells' lowest vertex: 1 m plus 1 mm per m of distance,
// for float rounding of the mesh and the chord of a cell below the curved shell (as the CPU's
// terrain/screen_horizon.cpp).
const float kMarginM = 1.0, kMarginPerM = 1e-3;
// Half a diagonal, with 1 % for the spread of the footprint at height.
const float kHalfDiagonal = 0.5 * 1.4142135 * 1.01;
// Added to a target's highest point for float rounding (m); its nearest distance is taken from
// the chunk's point nearest the planet's centre, for the skirts that hang below the cells.
const float kTargetMarginM = 1.0;

// Per chunk, per block: x: the tangent of its occluder (kNoOccluder: none); y, z: its azimuth span
// (bins); w: its farthest horizontal distance (m).
shared vec4 blocks[kBlockChunksPerGroup][kBlocksPerChunk];

vec4 BlockOfStrip(uint chunk, uint strip, uint k) {
  uint line = strip % kChunkBlocks;
  return blocks[chunk][strip < kChunkBlocks ? line * kChunkBlocks + k : k * kChunkBlocks + line];
}

// A sea-level point's vertical minus the camera's, its z without cancelling: both are nearly 1
// (scene/terrain.h's SurfacePoint: the vertical at (x, y) is (x / R, y / R, sqrt(1 - q))).
vec3 OffsetFromCameraVertical(vec2 xy) {
  const float R = east.w;
  const vec3 u = vertical.xyz;
  float q = dot(xy, xy) / (R * R), q_camera = dot(u.xy, u.xy);
  return vec3(xy / R - u.xy, (q_camera - q) / (sqrt(1.0 - q) + u.z));
}

// The offset's part in the camera's horizontal plane (east, north).
vec2 Horizontal(vec3 offset) { return vec2(dot(offset, east.xyz), dot(offset, north.xyz)); }

float HorizontalLength(vec2 xy) { return length(Horizontal(OffsetFromCameraVertical(xy))); }

// A sea-level point's direction seen from the camera's vertical: x: azimuth (bins), y: horizontal
// length, z: drop below the camera's horizontal plane (1 - cos of the angle between the two verticals).
vec3 SeenFromCamera(vec2 xy) {
  const vec3 offset = OffsetFromCameraVertical(xy);
  const vec2 horizontal = Horizontal(offset);
  return vec3(AzimuthInBins(atan(horizontal.y, horizontal.x)), length(horizontal), 0.5 * dot(offset, offset));
}

void main() {
  const uint chunk = gl_LocalInvocationIndex / kBlocksPerChunk, t = gl_LocalInvocationIndex % kBlocksPerChunk;
  const uint index = gl_WorkGroupID.x * kBlockChunksPerGroup + chunk;
  const bool present = index < candidates;
  const int slot = present ? int(keys[index].y) : 0;
  const ivec3 id = nodes[slot].id.xyz;
  const float R = east.w;
  const float block_size = ChunkSize(id.x) / float(kChunkBlocks);
  const vec2 origin = ChunkOrigin(id);
  // A chunk around the camera's vertical has no span of azimuths; those near it add nothing.
  const float chunk_size = float(kChunkBlocks) * block_size;
  const float nearest =
      min(min(HorizontalLength(origin), HorizontalLength(origin + vec2(chunk_size, 0.0))),
          min(HorizontalLength(origin + vec2(0.0, chunk_size)), HorizontalLength(origin + chunk_size)));
  const bool usable = present && nearest * R > kHalfDiagonal * chunk_size;
  {
    const uint i = t % kChunkBlocks, j = t / kChunkBlocks;
    // Each block finds its own corners, though neighbours share them: a CPU device reads shared
    // memory a lane at a time, and sharing them cost more than the arithmetic.
    vec3 block_corners[4];
    for (int k = 0; k < 4; ++k)
      block_corners[k] = SeenFromCamera(origin + vec2(i + uint(k & 1), j + uint(k >> 1)) * block_size);
    const vec2 heights = block_heights[uint(slot) * kBlocksPerChunk + t];
    const float lowest = heights.x, highest = heights.y;
    const float reference = SeenFromCamera(origin).x;
    // At the height of the lowest vertex, to a ray's distance from the camera (height, horizontal).
    vec3 first_corner = block_corners[0];
    vec2 seen = vec2(lowest - vertical.w - (R + lowest) * first_corner.z, (R + lowest) * first_corner.y);
    const float h = lowest - kMarginM - kMarginPerM * length(seen);
    float z_min = 1e30, near_unit = 1e30, far_unit = 0.0, span_min = 1e30, span_max = -1e30;
    for (int k = 0; k < 4; ++k) {
      vec3 c = block_corners[k];
      z_min = min(z_min, h - vertical.w - (R + h) * c.z);
      near_unit = min(near_unit, c.y);
      far_unit = max(far_unit, c.y);
      float azimuth = UnwrapBins(c.x, reference);
      span_min = min(span_min, azimuth);
      span_max = max(span_max, azimuth);
    }
    // Tangents z / d over the block are at least its lowest z over the nearest distance when z < 0
    // and over the farthest one otherwise; the nearest is no closer than the nearest corner less
    // half a diagonal.
    near_unit -= kHalfDiagonal * block_size / R;
    const float near = (R + h) * near_unit, far = (R + h) * far_unit;
    float tangent = near <= 0.0 ? kNoOccluder : z_min / (z_min < 0.0 ? near : far);
    blocks[chunk][t] = vec4(tangent, span_min, span_max, far * 1.001);

    // The drop (1 - cos) of a point of the block is at least half its horizontal length squared.
    const float z_max = highest - vertical.w - (R + highest) * 0.5 * near_unit * near_unit + kTargetMarginM;
    const vec3 center = vec3(0.0, 0.0, -R);
    const float r_lowest = length(clamp(center, nodes[slot].lower.xyz, nodes[slot].upper.xyz) - center) - kTargetMarginM;
    const float target_near = r_lowest * near_unit;
    const int band = usable && near_unit > 0.0 ? HorizonBandWithin(target_near) : -1;
    const float target = z_max / (z_max >= 0.0 ? target_near : (R + highest) * far_unit * 1.001);
    // The ground over the block lies between its heights: at height h over the sea-level point
    // (x, y), z is -R + (R + h) sqrt(1 - q) (SurfacePoint), at most h and, as sqrt(1 - q) >= 1 - q,
    // at least h - (R + h) q; q = (x^2 + y^2) / R^2 is largest at the block's farthest corner.
    const vec2 lower = origin + vec2(i, j) * block_size, upper = lower + block_size;
    const vec2 farthest = max(abs(lower), abs(upper));
    const float q = dot(farthest, farthest) / (R * R);
    const bool in_view = FootprintMayBeInFrustum(lower, upper, lowest - (R + lowest) * q - kTargetMarginM,
                                                 highest + kTargetMarginM);
    if (present) targets[index * kBlocksPerChunk + t] = vec4(target, span_min, span_max, in_view ? float(band) : kOutsideView);
  }
  barrier();
  if (!usable) return;

  // Rows (strips 0-3, along x) and columns (4-7, along y) of blocks, 2 invocations a strip.
  const uint strip = t % (2u * kChunkBlocks), lane = t / (2u * kChunkBlocks);
  float span_min = 1e30, span_max = -1e30, far = 0.0;
  bool whole = true;
  for (uint k = 0u; k < kChunkBlocks; ++k) {
    vec4 b = BlockOfStrip(chunk, strip, k);
    whole = whole && b.x > kNoOccluder;
    span_min = min(span_min, b.y);
    span_max = max(span_max, b.z);
    far = max(far, b.w);
  }
  const int band = HorizonBandReaching(far);
  if (!whole || band >= kHorizonBands) return;
  // The bins wholly within the strip's span.
  for (int bin = int(ceil(span_min)) + int(lane); float(bin + 1) <= span_max; bin += 2) {
    float tangent = 1e30, within = kNoOccluder;
    for (uint k = 0u; k < kChunkBlocks; ++k) {
      vec4 b = BlockOfStrip(chunk, strip, k);
      if (b.z >= float(bin) && b.y <= float(bin + 1)) tangent = min(tangent, b.x);
      if (b.y <= float(bin) && b.z >= float(bin + 1)) within = max(within, b.x);
    }
    atomicMax(horizon[HorizonIndex(band, bin)], OrderedBits(max(tangent, within)));
  }
}
