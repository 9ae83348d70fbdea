#version 450
#extension GL_GOOGLE_include_directive : require
// Composite pass, per pixel: nu from the pixel's own view ray, the Rayleigh and Cornette-Shanks
// phase functions, and L = L_surface T + I_R P_R(nu) + I_M P_M(nu) with (I_R, I_M, T) read from
// the froxel volume at the pixel's distance (or, in per-pixel mode, straight from the tables).
// Sky pixels take the inscatter along the whole ray from the per-frame sky-view table (per-pixel
// mode: from the tables), plus the sun disc; pixels
// whose ray meets the planet beyond the scene's geometry see the bare ground (ground albedo).
// A fragment pass over a full-screen triangle: on a CPU rasterizer this runs far faster than the
// same work as a compute shader with storage-image access.
#include "froxel.glsl"
#include "frame.glsl"
#include "surface.glsl"
#include "sky_view.glsl"
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler3D rayleigh_froxels;
layout(set = 0, binding = 7) uniform sampler3D mie_froxels;
layout(set = 0, binding = 8) uniform sampler3D transmittance_froxels;
layout(set = 0, binding = 9) uniform sampler2D surface_texture;  // a < 0: no geometry
layout(set = 0, binding = 10) uniform sampler2D irradiance_texture;
layout(set = 0, binding = 11) uniform sampler2D rayleigh_sky;
layout(set = 0, binding = 12) uniform sampler2D mie_sky;
layout(set = 0, binding = 13) uniform sampler2D transmittance_sky;

// The whole view ray's inscatter: from the sky-view table, or (per-pixel mode) from the tables.
Inscatter GetPixelSky(vec3 ray, float r, float mu, float mu_s, float nu) {
  if (kAerialPerPixel == 1) {
    return GetSkyInscatter(transmittance_texture, rayleigh_texture, mie_texture, multiple_texture,
                           r, mu, mu_s, nu);
  }
  vec3 up, toward_sun, side;
  GetSkyViewFrame(up, toward_sun, side);
  vec3 horizontal = ray - mu * up;
  float cos_phi = dot(horizontal, horizontal) > 1e-12 ? dot(normalize(horizontal), toward_sun) : 1.0;
  vec2 uv = GetSkyViewUv(r, cos_phi, acos(clamp(mu, -1.0, 1.0)), textureSize(rayleigh_sky, 0));
  Inscatter sky;
  sky.rayleigh = textureLod(rayleigh_sky, uv, 0.0).rgb;
  sky.mie = textureLod(mie_sky, uv, 0.0).rgb;
  sky.transmittance = textureLod(transmittance_sky, uv, 0.0).rgb;
  return sky;
}
layout(location = 0) out vec4 color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec2 uv = gl_FragCoord.xy / frame.viewport.xy;
  vec3 ray = ViewRayFromScreen(uv);
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  vec4 surface = texelFetch(surface_texture, pixel, 0);
  vec3 radiance;
  if (surface.a < 0.0) {
    Inscatter sky = GetPixelSky(ray, r, mu, mu_s, nu);
    radiance = ApplyPhaseFunctions(sky, nu);
    if (RayIntersectsGround(r, mu)) {
      vec3 ground = ray * DistanceToBottomAtmosphereBoundary(r, mu);
      vec3 normal = normalize(frame.camera_planet_position.xyz + ground);
      radiance += sky.transmittance * ShadeLambertian(transmittance_texture, irradiance_texture,
                                                      ground, normal, atmosphere.ground_albedo.rgb);
    } else if (nu > cos(atmosphere.sun_angular_radius)) {
      // The sun disc at its true angular size, seen through the atmosphere.
      radiance += GetSolarRadiance() * sky.transmittance;
    }
  } else {
    Inscatter segment;
    if (kAerialPerPixel == 1) {
      segment = GetSkyInscatterToPoint(transmittance_texture, rayleigh_texture, mie_texture,
                                       multiple_texture, r, mu, mu_s, nu, surface.a);
    } else {
      segment = SampleFroxels(rayleigh_froxels, mie_froxels, transmittance_froxels, uv, surface.a,
                              float(frame.froxel_size.z), frame.froxel_depth.x);
    }
    radiance = surface.rgb * segment.transmittance + ApplyPhaseFunctions(segment, nu);
  }
  color = vec4(radiance, 1.0);
}
