#version 450
#extension GL_GOOGLE_include_directive : require
// The sky, drawn after the opaque geometry into the same target where none was drawn (the depth
// test passes only there): the inscatter of the whole view ray with the phase functions from the
// pixel's own ray, plus what lies behind it: the sun disc, or the bare planet where the ray meets
// the ground beyond the scene's geometry. In froxel mode it comes from the sky-view table in two
// bilinear taps (sky_view.comp: Rayleigh's phase and the bare planet are in the first), and the
// sun's disc is added after by a pass of its own around the disc (sun_disc.frag); in the per-pixel
// modes, all of it from the tables.
// The per-pixel sky's variant for a high sun (aerial/render/sun_high_variant.h,
// Renderer::SkyPipelineFor), declared before the includes so that transmittance.glsl takes it.
layout(constant_id = 4) const bool kSunHighEverywhere = false;
#define AERIAL_SUN_HIGH_EVERYWHERE kSunHighEverywhere
#include "aerial_perspective.glsl"
#include "sky_view.glsl"
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler2D irradiance_texture;
layout(set = 0, binding = 7) uniform sampler2D rayleigh_sky;  // with phase and the bare planet
layout(set = 0, binding = 8) uniform sampler2D mie_sky;
layout(location = 0) in vec3 view_ray;
layout(location = 1) flat in vec3 up;
layout(location = 2) flat in vec3 toward_sun;
layout(location = 3) flat in float table_horizon;  // the sky-view table's horizon's zenith angle
layout(location = 0) out vec4 color;


void main() {
  vec3 ray = normalize(view_ray);
  if (kAerialPerPixel != AERIAL_FROXELS) {
    color = vec4(GetSkyRadianceAlongRay(transmittance_texture, rayleigh_texture, mie_texture, multiple_texture,
                                        irradiance_texture, ray),
                 1.0);
    return;
  }
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  vec2 uv = GetSkyViewUvOfRay(ray, mu, up, toward_sun, table_horizon, textureSize(rayleigh_sky, 0));
  color = vec4(textureLod(rayleigh_sky, uv, 0.0).rgb +
                   textureLod(mie_sky, uv, 0.0).rgb * MiePhaseFunction(AERIAL_ATMOSPHERE.mie_phase_g, nu),
               1.0);
}
