#version 450
#extension GL_GOOGLE_include_directive : require
// Froxel pass: for each froxel, the inscatter (Rayleigh and Mie, without phase) and transmittance
// from the camera to its slice's distance along the ray through its screen-space center
// (Bruneton 2008 eq. 16, S(x, v) - T(x, p) S(p, v), from the 4D or 3D tables). One invocation
// walks one froxel column: S(x, v) is the same for all its slices and is read once.
#include "froxel.glsl"
#include "frame.glsl"
// Wide in x: a CPU implementation vectorizes across the invocations of a workgroup's rows.
layout(local_size_x = 32, local_size_y = 1) in;
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) writeonly uniform image3D rayleigh_froxels;
layout(set = 0, binding = 7) writeonly uniform image3D mie_froxels;
layout(set = 0, binding = 8) writeonly uniform image3D transmittance_froxels;

void main() {
  ivec2 column = ivec2(gl_GlobalInvocationID.xy);
  ivec3 size = frame.froxel_size.xyz;
  if (any(greaterThanEqual(column, size.xy))) return;
  vec3 ray = ViewRayFromScreen((vec2(column) + 0.5) / vec2(size.xy));
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  Inscatter ray_scattering = GetRayScattering(rayleigh_texture, mie_texture, multiple_texture, r,
                                              mu, mu_s, nu, RayIntersectsGround(r, mu));
  for (int slice = 0; slice < size.z; ++slice) {
    float distance = FroxelSliceDistance(float(slice) + 0.5, float(size.z), frame.froxel_depth.x);
    Inscatter inscatter = GetSkyInscatterToPointFrom(ray_scattering, transmittance_texture,
                                                     rayleigh_texture, mie_texture,
                                                     multiple_texture, r, mu, mu_s, nu, distance);
    ivec3 froxel = ivec3(column, slice);
    imageStore(rayleigh_froxels, froxel, vec4(inscatter.rayleigh, 0.0));
    imageStore(mie_froxels, froxel, vec4(inscatter.mie, 0.0));
    imageStore(transmittance_froxels, froxel, vec4(inscatter.transmittance, 1.0));
  }
}
