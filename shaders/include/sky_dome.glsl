// The sky dome (sky_dome.vert): the sky-view table's directions as a mesh around the camera, a
// grid of SKY_DOME_COLUMNS cells over the table's azimuth [0, pi] (drawn twice, once mirrored,
// for the other side of the sun's vertical plane) and SKY_DOME_ROWS rows over each half of its
// zenith axis, above and below the horizon, so that no triangle straddles the horizon. Its vertices
// lie on the table's own coordinate grid, where the mapping from direction to table coordinates is
// smooth: within a cell of a few degrees it is linear to a small fraction of a texel, so the
// fragments interpolate the vertices' coordinates instead of evaluating the mapping (two arc
// cosines and a square root) per pixel. The rows follow the table's, dense near the horizon.
// These lines are also C++ (src/aerial/render/sky_view_layout.h counts the dome's vertices).
#ifndef AERIAL_SKY_DOME_GLSL
#define AERIAL_SKY_DOME_GLSL

const int SKY_DOME_COLUMNS = 24;
const int SKY_DOME_ROWS = 16;

#endif
