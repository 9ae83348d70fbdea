#version 450
#extension GL_GOOGLE_include_directive : require
// Debug view of one depth slice of the froxel volume: three columns, left to right the Rayleigh
// inscatter, the Mie inscatter and the transmittance of slice k (from the camera to the slice's
// distance, far ((k + 0.5) / D)^2, froxel.glsl). Each froxel is one flat block, read without
// filtering. The inscatter is stored without phase, so it is shown as if scattered isotropically
// (times 1 / 4 pi) with the exposure and the tone map; the transmittance is only sRGB-encoded.
#include "definitions.glsl"
#include "display.glsl"
layout(set = 0, binding = 0) uniform sampler3D rayleigh_froxels;
layout(set = 0, binding = 1) uniform sampler3D mie_froxels;
layout(set = 0, binding = 2) uniform sampler3D transmittance_froxels;
layout(push_constant) uniform Push {
  vec2 target_size;  // the window's pixels
  int slice;
  float exposure;
} push;
layout(location = 0) out vec4 color;  // 8-bit, RGBA or BGRA

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ivec2 size = ivec2(push.target_size);
  int column = min(pixel.x * 3 / size.x, 2);
  float column_width = float(size.x) / 3.0;
  vec2 within = vec2((float(pixel.x) - column * column_width) / column_width,
                     float(pixel.y) / float(size.y));
  ivec3 grid = textureSize(rayleigh_froxels, 0);
  ivec3 froxel = ivec3(min(ivec2(within * vec2(grid.xy)), grid.xy - 1),
                       clamp(push.slice, 0, grid.z - 1));
  vec3 value;
  if (column == 0) {
    value = ToneMapLinearWithoutToe(texelFetch(rayleigh_froxels, froxel, 0).rgb * push.exposure / (4.0 * PI));
  } else if (column == 1) {
    value = ToneMapLinearWithoutToe(texelFetch(mie_froxels, froxel, 0).rgb * push.exposure / (4.0 * PI));
  } else {
    value = (clamp(texelFetch(transmittance_froxels, froxel, 0).rgb, 0.0, 1.0));
  }
  color = DisplayColor(value);
}
