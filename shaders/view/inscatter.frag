#version 450
#extension GL_GOOGLE_include_directive : require
// Debug views of the aerial perspective alone, per pixel: the Rayleigh term I_R P_R(nu), the Mie
// term I_M P_M(nu) or the transmittance T of L = L_surface T + I_R P_R + I_M P_M (the composite's
// equation). For pixels with geometry the segment ends at the surface (its distance from the
// depth buffer) and is read from the froxel volume in froxel mode, exactly as the composite reads
// it, or from the tables in per-pixel mode. For sky pixels the whole view ray is read from the
// tables: the renderer's per-frame sky-view table is internal to it (it resamples these same
// lookups). Left out: the surface's own radiance and the sun disc. Inscatter is tone mapped with
// the exposure; transmittance, already in [0, 1], is only sRGB-encoded.
#include "aerial_perspective.glsl"
#include "frame.glsl"
#include "display.glsl"
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler3D multiple_density_texture;
layout(set = 0, binding = 7) uniform sampler3D rayleigh_froxels;
layout(set = 0, binding = 8) uniform sampler3D mie_froxels;
layout(set = 0, binding = 9) uniform sampler3D transmittance_froxels;
layout(set = 0, binding = 10) uniform sampler2D depth_texture;  // reversed Z, 0 where sky
layout(push_constant) uniform Push {
  vec2 target_size;  // the window's pixels
  int term;          // 0: Rayleigh, 1: Mie, 2: transmittance
  int from_froxels;  // 1 in froxel mode
  float exposure;
} push;
layout(location = 0) out vec4 color;  // 8-bit, RGBA or BGRA

void main() {
  vec2 uv = gl_FragCoord.xy / push.target_size;
  vec3 ray = ViewRayFromScreen(uv);
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  // The renderer's own depth texel under the pixel (its frame may be smaller: --render-scale).
  float depth = texelFetch(depth_texture, ivec2(uv * AERIAL_FRAME.viewport.xy), 0).r;
  float distance = DistanceFromDepth(uv, depth);
  Inscatter segment;
  if (depth == 0.0) {
    segment = GetSkyInscatter(transmittance_texture, rayleigh_texture, mie_texture,
                              multiple_texture, r, mu, mu_s, nu);
  } else if (push.from_froxels == 1) {
    segment = GetAerialPerspective(rayleigh_froxels, mie_froxels, transmittance_froxels, uv, distance);
  } else {
    segment = GetSkyInscatterToPoint(transmittance_texture, multiple_density_texture, r, mu,
                                     mu_s, nu, distance);
  }
  vec3 value;
  if (push.term == 0) {
    value = ToneMapLinearWithoutToe(segment.rayleigh * RayleighPhaseFunction(nu) * push.exposure);
  } else if (push.term == 1) {
    value = ToneMapLinearWithoutToe(segment.mie * MiePhaseFunction(AERIAL_ATMOSPHERE.mie_phase_g, nu) * push.exposure);
  } else {
    value = (clamp(segment.transmittance, 0.0, 1.0));
  }
  color = DisplayColor(value);
}
