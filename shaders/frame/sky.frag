#version 450
#extension GL_GOOGLE_include_directive : require
// The sky of the per-pixel modes, drawn after the opaque geometry into the same target where none
// was drawn (the depth test passes only there): the whole view ray's inscatter from the tables
// with the phase functions of the pixel's own ray, plus what lies behind it, the sun disc or the
// bare planet where the ray meets the ground beyond the scene's geometry. Froxel mode draws the
// sky from the per-frame sky-view table instead (sky_dome.vert, sky_dome.frag).
// The variant for a high sun (aerial/render/sun_high_variant.h, Renderer::SkyPipelineFor),
// declared before the includes so that transmittance.glsl takes it.
layout(constant_id = 4) const bool kSunHighEverywhere = false;
#define AERIAL_SUN_HIGH_EVERYWHERE kSunHighEverywhere
#include "aerial_perspective.glsl"
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler2D irradiance_texture;
layout(location = 0) in vec3 view_ray;
layout(location = 0) out vec4 color;

void main() {
  color = vec4(GetSkyRadianceAlongRay(transmittance_texture, rayleigh_texture, mie_texture, multiple_texture,
                                      irradiance_texture, normalize(view_ray)),
               1.0);
}
