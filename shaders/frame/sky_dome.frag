#version 450
#extension GL_GOOGLE_include_directive : require
// The sky in froxel mode (sky_dome.vert): the whole view ray's Rayleigh and Mie inscatter from the
// sky-view table, with the phase functions of the pixel's own ray, plus what lies behind it: the
// sun's disc, or the bare planet where the ray meets the ground beyond the scene's geometry.
#include "sky_view.glsl"
#include "surface.glsl"
layout(set = 0, binding = 7) uniform sampler2D rayleigh_sky;
layout(set = 0, binding = 8) uniform sampler2D mie_sky;
layout(location = 0) in vec2 sky_view_angles;
layout(location = 1) in vec3 view_ray;
layout(location = 2) in vec3 background;
layout(location = 3) flat in vec2 horizon;
layout(location = 0) out vec4 color;

void main() {
  bool below = horizon.y > 0.5;
  vec2 uv = GetSkyViewUv(horizon.x, sky_view_angles.x, sky_view_angles.y, below, textureSize(rayleigh_sky, 0));
  Inscatter sky = Inscatter(textureLod(rayleigh_sky, uv, 0.0).rgb, textureLod(mie_sky, uv, 0.0).rgb, vec3(1.0));
  float nu = dot(normalize(view_ray), frame.sun_direction.xyz);
  color = vec4(ApplyPhaseFunctions(sky, nu) + ShadeBackground(background, below, nu), 1.0);
}
