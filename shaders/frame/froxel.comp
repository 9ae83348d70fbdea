#version 450
#extension GL_GOOGLE_include_directive : require
// Froxel pass: for each froxel, the inscatter (Rayleigh and Mie, without phase) and transmittance
// from the camera to its slice's distance along the ray through its screen-space center
// (Bruneton 2008 eq. 16, S(x, v) - T(x, p) S(p, v), from the 4D or 3D tables).
#include "froxel.glsl"
#include "frame.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) writeonly uniform image3D rayleigh_froxels;
layout(set = 0, binding = 7) writeonly uniform image3D mie_froxels;
layout(set = 0, binding = 8) writeonly uniform image3D transmittance_froxels;

void main() {
  ivec3 froxel = ivec3(gl_GlobalInvocationID);
  ivec3 size = frame.froxel_size.xyz;
  if (any(greaterThanEqual(froxel, size))) return;
  vec3 ray = ViewRayFromScreen((vec2(froxel.xy) + 0.5) / vec2(size.xy));
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  float distance = FroxelSliceDistance(float(froxel.z) + 0.5, float(size.z), frame.froxel_depth.x);
  Inscatter inscatter = GetSkyInscatterToPoint(transmittance_texture, rayleigh_texture,
                                               mie_texture, multiple_texture, r, mu, mu_s, nu,
                                               distance);
  imageStore(rayleigh_froxels, froxel, vec4(inscatter.rayleigh, 0.0));
  imageStore(mie_froxels, froxel, vec4(inscatter.mie, 0.0));
  imageStore(transmittance_froxels, froxel, vec4(inscatter.transmittance, 1.0));
}
