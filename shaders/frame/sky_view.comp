#version 450
#extension GL_GOOGLE_include_directive : require
// Sky-view pass: fills the per-frame sky-view table (sky_view.glsl) from the 4D or 3D tables.
#include "sky_view.glsl"
#include "surface.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler2D irradiance_texture;
layout(set = 0, binding = 7) writeonly uniform image2D rayleigh_sky;
layout(set = 0, binding = 8) writeonly uniform image2D mie_sky;
layout(set = 0, binding = 9) writeonly uniform image2D background_sky;
layout(push_constant) uniform Size { ivec2 size; } table;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, table.size))) return;
  float r = length(frame.camera_planet_position.xyz);
  vec2 direction = GetSkyViewDirection(r, (vec2(texel) + 0.5) / vec2(table.size), table.size);
  vec3 up, toward_sun, side;
  GetSkyViewFrame(up, toward_sun, side);
  float sin_theta = sin(direction.y);
  vec3 ray = up * cos(direction.y) +
             sin_theta * (toward_sun * direction.x + side * sqrt(max(1.0 - direction.x * direction.x, 0.0)));
  float mu = dot(up, ray);
  float mu_s = dot(up, frame.sun_direction.xyz);
  float nu = dot(ray, frame.sun_direction.xyz);
  Inscatter sky = GetSkyInscatter(transmittance_texture, rayleigh_texture, mie_texture,
                                  multiple_texture, r, mu, mu_s, nu);
  imageStore(rayleigh_sky, texel, vec4(sky.rayleigh, 0.0));
  imageStore(mie_sky, texel, vec4(sky.mie, 0.0));
  vec3 background = GetBackgroundThroughAtmosphere(transmittance_texture, irradiance_texture, ray,
                                                   r, mu, sky.transmittance);
  imageStore(background_sky, texel, vec4(background, 1.0));
}
