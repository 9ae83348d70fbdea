// The lattice of the sky inscatter correction (sky_view_correction.comp) over the sky-view table:
// nodes every 4 texels in azimuth and 3 in zenith, each half of the zenith axis (above and below
// the horizon, where the correction jumps with the ray's end) on its own nodes, and the last
// texel of each axis or half a node too, so that texels only interpolate between nodes.
// Its shape (spacing, node counts) is written in the subset of GLSL that is also C++:
// src/aerial/render/sky_view_layout.h includes this file too and sizes the lattice's images with
// the same lines; the rest is GLSL only.
#ifndef AERIAL_SKY_VIEW_LATTICE_GLSL
#define AERIAL_SKY_VIEW_LATTICE_GLSL
#ifdef __cplusplus
#define AERIAL_SHARED_FUNCTION constexpr
#else
#define AERIAL_SHARED_FUNCTION
#endif

const int SKY_VIEW_LATTICE_SPACING_X = 4;  // texels between nodes in azimuth
const int SKY_VIEW_LATTICE_SPACING_Y = 3;  // and in zenith, in each half

// Along an axis of n texels: the node count.
AERIAL_SHARED_FUNCTION int GetLatticeNodeCount(int n, int spacing) { return (n - 2) / spacing + 2; }

// The lattice's size for a table of width x height texels.
AERIAL_SHARED_FUNCTION int GetSkyViewLatticeWidth(int width) {
  return GetLatticeNodeCount(width, SKY_VIEW_LATTICE_SPACING_X);
}
AERIAL_SHARED_FUNCTION int GetSkyViewLatticeHeight(int height) {
  return 2 * GetLatticeNodeCount(height / 2, SKY_VIEW_LATTICE_SPACING_Y);
}

#undef AERIAL_SHARED_FUNCTION

#ifndef __cplusplus
// Along an axis of n texels: the texel of node i.
int GetLatticeNodeTexel(int i, int n, int spacing) { return min(i * spacing, n - 1); }

// The node at or below texel x, and the weight of the one after it.
void GetLatticeCell(int x, int n, int spacing, out int i, out float t) {
  i = min(x / spacing, GetLatticeNodeCount(n, spacing) - 2);
  int x0 = GetLatticeNodeTexel(i, n, spacing);
  t = float(x - x0) / float(GetLatticeNodeTexel(i + 1, n, spacing) - x0);
}

ivec2 GetSkyViewLatticeSize(ivec2 size) {
  return ivec2(GetSkyViewLatticeWidth(size.x), GetSkyViewLatticeHeight(size.y));
}

ivec2 GetSkyViewLatticeTexel(ivec2 node, ivec2 size) {
  int half_rows = size.y / 2;
  int half_nodes = GetLatticeNodeCount(half_rows, SKY_VIEW_LATTICE_SPACING_Y);
  int half_index = node.y / half_nodes;
  return ivec2(GetLatticeNodeTexel(node.x, size.x, SKY_VIEW_LATTICE_SPACING_X),
               half_index * half_rows +
                   GetLatticeNodeTexel(node.y - half_index * half_nodes, half_rows, SKY_VIEW_LATTICE_SPACING_Y));
}

// The lattice cell of a texel: its first node, and the weights of the next ones in x and y.
void GetSkyViewLatticeCell(ivec2 texel, ivec2 size, out ivec2 node, out vec2 t) {
  int half_rows = size.y / 2;
  int half_index = texel.y / half_rows;
  GetLatticeCell(texel.x, size.x, SKY_VIEW_LATTICE_SPACING_X, node.x, t.x);
  GetLatticeCell(texel.y - half_index * half_rows, half_rows, SKY_VIEW_LATTICE_SPACING_Y, node.y, t.y);
  node.y += half_index * GetLatticeNodeCount(half_rows, SKY_VIEW_LATTICE_SPACING_Y);
}
#endif  // __cplusplus
#endif
