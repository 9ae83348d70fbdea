// The froxel volume: a grid aligned with the camera frustum, x and y across the screen (its rows
// gathered around the horizon and its columns at the sun's glow, froxel_axes.glsl), z along the
// view distance with quadratic slices (froxel_depth.glsl). Each froxel holds, from the camera to
// its slice's distance along its center ray, Rayleigh and Mie inscatter WITHOUT phase and the
// transmittance: phases are applied per pixel.
#ifndef AERIAL_FROXEL_GLSL
#define AERIAL_FROXEL_GLSL
#include "froxel_depth.glsl"
#include "froxel_axes.glsl"
#include "sky_lookup.glsl"

// Trilinear read at a screen position and a distance; columns, rows: the frame's froxel_columns
// and froxel_rows. Below the first slice center the values are blended toward the empty segment
// (no inscatter, full transmittance), since the sampler would otherwise clamp to the first slice.
Inscatter SampleFroxels(sampler3D rayleigh_froxels, sampler3D mie_froxels,
                        sampler3D transmittance_froxels, vec2 uv, float distance,
                        float slices, float far_distance, vec4 columns, vec4 rows) {
  vec3 uvw = vec3(FroxelAxesCoordinates(uv, columns, rows), FroxelDepthCoordinate(distance, far_distance));
  Inscatter result;
  result.rayleigh = textureLod(rayleigh_froxels, uvw, 0.0).rgb;
  result.mie = textureLod(mie_froxels, uvw, 0.0).rgb;
  result.transmittance = textureLod(transmittance_froxels, uvw, 0.0).rgb;
  float first = FroxelSliceDistance(0.5, slices, far_distance);
  if (distance < first) {
    float t = distance / first;
    result.rayleigh *= t;
    result.mie *= t;
    result.transmittance = mix(vec3(1.0), result.transmittance, t);
  }
  return result;
}

#endif
