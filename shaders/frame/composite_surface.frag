#version 450
#extension GL_GOOGLE_include_directive : require
// Composite, pixels with geometry (the depth test passes only where the opaque pass drew): nu from
// the pixel's own view ray, the Rayleigh and Cornette-Shanks phase functions, and
// L = L_surface T + I_R P_R(nu) + I_M P_M(nu) with (I_R, I_M, T) read from the froxel volume at the
// pixel's distance (per-pixel mode: straight from the tables).
#include "froxel.glsl"
#include "frame.glsl"
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler3D rayleigh_froxels;
layout(set = 0, binding = 7) uniform sampler3D mie_froxels;
layout(set = 0, binding = 8) uniform sampler3D transmittance_froxels;
layout(set = 0, binding = 9) uniform sampler2D surface_texture;  // rgb: radiance, a: distance
layout(location = 0) out vec4 color;

void main() {
  vec2 uv = gl_FragCoord.xy / frame.viewport.xy;
  vec3 ray = ViewRayFromScreen(uv);
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  vec4 surface = texelFetch(surface_texture, ivec2(gl_FragCoord.xy), 0);
  Inscatter segment;
  if (kAerialPerPixel == 1) {
    segment = GetSkyInscatterToPoint(transmittance_texture, rayleigh_texture, mie_texture,
                                     multiple_texture, r, mu, mu_s, nu, surface.a);
  } else {
    segment = SampleFroxels(rayleigh_froxels, mie_froxels, transmittance_froxels, uv, surface.a,
                            float(frame.froxel_size.z), frame.froxel_depth.x);
  }
  color = vec4(surface.rgb * segment.transmittance + ApplyPhaseFunctions(segment, nu), 1.0);
}
