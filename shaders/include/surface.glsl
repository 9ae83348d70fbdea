// Lighting of opaque and transparent surfaces by the sun (through the transmittance table, with
// the visible part of its disc) and the sky (through the irradiance table, cosine-weighted for a
// tilted normal as in Bruneton 2017 "GetSunAndSkyIrradiance"). Lambertian: L = albedo / pi * E.
#ifndef AERIAL_SURFACE_GLSL
#define AERIAL_SURFACE_GLSL
#include "frame.glsl"
#include "sky_lookup.glsl"

// The radiance leaving a Lambertian surface in its two parts: what the sun lights directly (the
// part a shadow takes away) and what the sky lights (never shadowed here: the sky is seen from
// most of the hemisphere even beside a mountain). `sun` is for a surface facing the sun: its
// cosine is left to ShadeLambertian, per fragment, because interpolating the vertices' clamped
// cosines across a triangle blurs the terminator on a slope turned from the sun and lights its
// dark side (with the sun 55 degrees from the zenith, a terrain pixel just past it was 2.4x the
// CPU reference's radiance in `aerial bench --quick`).
struct LambertianRadiance {
  vec3 sun;
  vec3 sky;
};

LambertianRadiance GetLambertianRadiance(sampler2D transmittance_texture, sampler2D irradiance_texture,
                                         vec3 relative_position, vec3 normal, vec3 albedo) {
  vec3 point = AERIAL_FRAME.camera_planet_position.xyz + relative_position;
  float r = length(point);
  vec3 up = point / r;
  vec3 sun = AERIAL_FRAME.sun_direction.xyz;
  float mu_s = dot(up, sun);
  vec3 sun_irradiance = GetDirectSunlight(transmittance_texture, r, mu_s, GetHorizonCosine(r), false);
  vec3 sky_irradiance = GetIrradiance(irradiance_texture, r, mu_s) * (1.0 + dot(normal, up)) * 0.5;
  return LambertianRadiance(albedo * (1.0 / PI) * sun_irradiance, albedo * (1.0 / PI) * sky_irradiance);
}

// The surface's radiance where its unit normal is `normal` and the fraction sun_visibility of the
// sun is seen (shadow.glsl).
vec3 ShadeLambertian(LambertianRadiance radiance, vec3 normal, float sun_visibility) {
  return radiance.sun * (max(dot(normal, AERIAL_FRAME.sun_direction.xyz), 0.0) * sun_visibility) + radiance.sky;
}

// What a view ray from the camera sees behind the atmosphere, through it: where the ray meets the
// planet, the lit bare ground times the ray's transmittance; elsewhere the transmittance alone,
// which the caller turns into the sun disc where the pixel's own ray falls inside it.
vec3 GetBackgroundThroughAtmosphere(sampler2D transmittance_texture, sampler2D irradiance_texture,
                                    vec3 ray, float r, float mu, vec3 transmittance) {
  if (!RayIntersectsGround(r, mu)) return transmittance;
  vec3 ground = ray * DistanceToBottomAtmosphereBoundary(r, mu);
  vec3 normal = normalize(AERIAL_FRAME.camera_planet_position.xyz + ground);
  return transmittance * ShadeLambertian(GetLambertianRadiance(transmittance_texture, irradiance_texture,
                                                               ground, normal, AERIAL_ATMOSPHERE.ground_albedo.rgb),
                                         normal, 1.0);
}

// sin^2 of the angle between a unit view ray and the sun's direction, from their cross product: on
// the disc 1 - nu is below 1.1e-5, where a float's step is 6e-8, so 1 - nu^2 would keep two or three
// digits and two rays a rounding apart would see the limb percents apart; the cross product keeps
// a float's precision there.
float SineSquaredFromSun(vec3 ray) {
  vec3 c = cross(ray, AERIAL_FRAME.sun_direction.xyz);
  return dot(c, c);
}

// The sun's limb darkening at a point of its disc whose angle from the disc's centre has the sine
// squared sine_squared (SineSquaredFromSun): the radiance there over the disc's mean radiance. The power law I(mu) = I(1) mu^alpha of Hestroffer
// & Magnan 1998 ("Wavelength dependency of the Solar limb darkening", A&A 333), fitted to Neckel
// & Labs 1994, with mu the cosine on the sun's surface and alpha = -0.023 + 0.292 / lambda[um]:
// 0.406, 0.508 and 0.641 at the channels' 680, 550 and 440 nm, the limb redder and dimmer than the
// centre. The mean of mu^alpha over the disc's area is 1 / (1 + alpha / 2), whose inverse keeps
// the disc's irradiance.
vec3 SunLimbDarkening(float sine_squared) {
  const vec3 alpha = vec3(0.406, 0.508, 0.641);
  float sin_radius = sin(AERIAL_ATMOSPHERE.sun_angular_radius);
  float off_centre = sine_squared / (sin_radius * sin_radius);  // sin^2 of the angle on the surface
  return pow(vec3(SafeSqrt(1.0 - off_centre)), alpha) * (1.0 + 0.5 * alpha);
}

// The sky pixel's radiance behind the inscatter: the background where the ray meets the ground
// (RayIntersectsGround), or on the sun disc (at its true angular size, limb-darkened) the sun seen
// through the atmosphere.
vec3 ShadeBackground(vec3 background, bool meets_ground, vec3 ray) {
  if (meets_ground) return background;
  float sine_squared = SineSquaredFromSun(ray);
  float sin_radius = sin(AERIAL_ATMOSPHERE.sun_angular_radius);
  bool on_disc = dot(ray, AERIAL_FRAME.sun_direction.xyz) > 0.0 && sine_squared < sin_radius * sin_radius;
  return on_disc ? GetSolarRadiance() * SunLimbDarkening(sine_squared) * background : vec3(0.0);
}

#endif
