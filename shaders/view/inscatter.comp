#version 450
#extension GL_GOOGLE_include_directive : require
// Debug views of the aerial perspective alone, per pixel: the Rayleigh term I_R P_R(nu), the Mie
// term I_M P_M(nu) or the transmittance T of L = L_surface T + I_R P_R + I_M P_M (the composite's
// equation). For pixels with geometry the segment ends at the surface (distance in the opaque
// pass's alpha) and is read from the froxel volume in froxel mode, exactly as the composite reads
// it, or from the tables in per-pixel mode. For sky pixels the whole view ray is read from the
// tables: the renderer's per-frame sky-view table is internal to it (it resamples these same
// lookups). Left out: the surface's own radiance and the sun disc. Inscatter is tone mapped with
// the exposure; transmittance, already in [0, 1], is only sRGB-encoded.
#include "froxel.glsl"
#include "frame.glsl"
#include "tone_map.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler3D rayleigh_froxels;
layout(set = 0, binding = 7) uniform sampler3D mie_froxels;
layout(set = 0, binding = 8) uniform sampler3D transmittance_froxels;
layout(set = 0, binding = 9) uniform sampler2D surface_texture;  // rgb: radiance, a: distance
layout(set = 0, binding = 10) writeonly uniform image2D display;  // 8-bit UNORM, RGBA or BGRA
layout(push_constant) uniform Push {
  int term;          // 0: Rayleigh, 1: Mie, 2: transmittance
  int from_froxels;  // 1 in froxel mode
  float exposure;
} push;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(display)))) return;
  vec2 uv = (vec2(pixel) + 0.5) / frame.viewport.xy;  // the composite's gl_FragCoord / viewport
  vec3 ray = ViewRayFromScreen(uv);
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  float distance = texelFetch(surface_texture, pixel, 0).a;  // negative: no geometry
  Inscatter segment;
  if (distance < 0.0) {
    segment = GetSkyInscatter(transmittance_texture, rayleigh_texture, mie_texture,
                              multiple_texture, r, mu, mu_s, nu);
  } else if (push.from_froxels == 1) {
    segment = SampleFroxels(rayleigh_froxels, mie_froxels, transmittance_froxels, uv, distance,
                            float(frame.froxel_size.z), frame.froxel_depth.x);
  } else {
    segment = GetSkyInscatterToPoint(transmittance_texture, rayleigh_texture, mie_texture,
                                     multiple_texture, r, mu, mu_s, nu, distance);
  }
  vec3 value;
  if (push.term == 0) {
    value = ToneMap(segment.rayleigh * RayleighPhaseFunction(nu) * push.exposure);
  } else if (push.term == 1) {
    value = ToneMap(segment.mie * MiePhaseFunction(atmosphere.mie_phase_g, nu) * push.exposure);
  } else {
    value = SrgbOetf(clamp(segment.transmittance, 0.0, 1.0));
  }
  imageStore(display, pixel, vec4(value, 1.0));
}
