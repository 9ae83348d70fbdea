// What the terrain's selection passes share (render/gpu_chunk_selection.h): the tree of built
// chunks and the view they are selected for.

const int kNotBuilt = -1;
const int kOutsideTerrain = -2;  // a child beyond the terrain's radius: never drawn
const int kMaxChunkLevel = 13;
const float kRootSizeM = 204800.0;
const int kChunkCells = 8;  // terrain::kChunkCells

struct ChunkNode {
  vec4 lower;         // the bounds' lower corner in the scene frame (m); w: geometric error (m)
  vec4 upper;         // the bounds' upper corner; w: the distance within which it reads the froxels per pixel
  ivec4 children;     // slots of the four children in terrain::Children order
  ivec4 neighbours;   // slots of the chunks of its level across its south, east, north, west sides
  ivec4 id;           // level, x, y; how many chunks the slot's tree had taken in before this one
};
layout(std430, set = 0, binding = 0) readonly buffer ChunkTree { ChunkNode nodes[]; };

layout(std140, set = 0, binding = 1) uniform SelectionView {
  vec4 planes[5];             // the frustum's sides and near plane (terrain::LodView::planes)
  vec4 camera;                // xyz: position; w: pixels per radian
  vec4 limits;                // x: error bound (px); y: resolved error (m); zw: the camera's sea-level x, y
  ivec4 root;                 // x: the root's slot or kNotBuilt; y: generation; z: vertices per slot; w: first instance
  vec4 vertical;              // xyz: the camera's local vertical; w: its height above the sea-level sphere (m)
  vec4 east;                  // xyz: a horizontal direction there, azimuth 0; w: the planet's radius (m)
  vec4 north;                 // xyz: the horizontal direction at azimuth 90 degrees; w: unused
  // x: 1 to compare the chunks drawn with the last selection's (TileContent); y: 1 to report them
  // changed whatever they are.
  uvec4 compare;
  uvec4 index_ranges[16];     // per skirt mask (terrain::ChunkIndexRange): first index, index count
  uvec4 block_firsts[16];     // per skirt mask, per block order: first index (terrain::ChunkBlockIndexRange)
};

float ChunkSize(int level) { return kRootSizeM / float(1 << level); }

// The chunk's sea-level footprint: its south-west corner (x, y) in meters.
vec2 ChunkOrigin(ivec3 id) { return -0.5 * kRootSizeM + vec2(id.yz) * ChunkSize(id.x); }

bool IntersectsFrustum(vec3 lower, vec3 upper) {
  for (int i = 0; i < 5; ++i) {
    // The box's corner furthest along the plane's normal.
    vec3 corner = mix(lower, upper, greaterThanEqual(planes[i].xyz, vec3(0.0)));
    if (dot(planes[i].xyz, corner) + planes[i].w < 0.0) return false;
  }
  return true;
}

// A point h above sea level sits at (R + h) / R times its sea-level x and y, so what stands on a
// sea-level footprint spreads past it by a little (lod_selection.cpp's kHorizontalSpread).
const float kHorizontalSpread = 2e-3;

// Whether ground over a sea-level footprint, between two heights of the scene frame, may be seen.
bool FootprintMayBeInFrustum(vec2 lower, vec2 upper, float lowest_z, float highest_z) {
  const vec2 margin = kHorizontalSpread * max(abs(lower), abs(upper)) + 1.0;
  return IntersectsFrustum(vec3(lower - margin, lowest_z), vec3(upper + margin, highest_z));
}
