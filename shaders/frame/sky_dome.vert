#version 450
#extension GL_GOOGLE_include_directive : require
// The sky in froxel mode, drawn as the sky dome (sky_dome.glsl) at infinity, after the opaque
// geometry: its fragments' depth is 0, the cleared depth, so the depth test (EQUAL) passes only
// where no geometry was drawn. Each vertex carries its direction and its angles in the sky-view
// table's frame (the fragments interpolate them and need no arc cosine), and what lies behind
// the sky along it, read here: the background (sky_view.comp) is smooth along the dome's rows and
// columns, which are denser than it changes.
#include "sky_dome.glsl"
#include "sky_view.glsl"
layout(set = 0, binding = 9) uniform sampler2D background_sky;
layout(location = 0) out vec2 sky_view_angles;  // x: the azimuth over pi, y: the zenith angle
layout(location = 1) out vec3 view_ray;
layout(location = 2) out vec3 background;
layout(location = 3) flat out vec2 horizon;  // x: the horizon's zenith angle, y: 1 below it

const ivec2 kCellCorners[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));

void main() {
  int cell = gl_VertexIndex / 6;
  ivec2 grid = ivec2(cell % SKY_DOME_COLUMNS, cell / SKY_DOME_COLUMNS % SKY_DOME_ROWS) + kCellCorners[gl_VertexIndex % 6];
  int below = cell / (SKY_DOME_COLUMNS * SKY_DOME_ROWS);
  ivec2 size = textureSize(background_sky, 0);
  vec2 uv = vec2(GetTextureCoordFromUnitRange(float(grid.x) / SKY_DOME_COLUMNS, size.x),
                 0.5 * float(below) + 0.5 * GetTextureCoordFromUnitRange(float(grid.y) / SKY_DOME_ROWS, size.y / 2));
  float r = length(frame.camera_planet_position.xyz);
  vec2 angles = GetSkyViewDirection(r, uv, size);
  sky_view_angles = vec2(float(grid.x) / SKY_DOME_COLUMNS, angles.y);
  view_ray = GetSkyViewRayDirection(angles, gl_InstanceIndex == 0 ? 1.0 : -1.0);
  background = textureLod(background_sky, uv, 0.0).rgb;
  horizon = vec2(HorizonZenithAngle(r), float(below));
  gl_Position = frame.view_projection * vec4(view_ray, 0.0);
}
