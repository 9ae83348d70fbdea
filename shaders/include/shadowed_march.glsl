// The sun's visibility along a camera ray's march through the air, from the shadow map
// (shadow.glsl): the froxel volume's columns (froxel.comp) and the marched per-pixel path
// (mesh_tables.glsl) shadow the single scattering of each step by the same rule, so that the one
// is measured against the other with shadows on (light shafts, mountain shadows in the air).
// The includer defines AERIAL_SHADOW_BINDING first (shadow.glsl).
#ifndef AERIAL_SHADOWED_MARCH_GLSL
#define AERIAL_SHADOWED_MARCH_GLSL
#include "frame.glsl"
#include "shadow.glsl"
#include "sky_lookup.glsl"

// The sun's visibility changes far faster than the air's light (a shadow edge), so each step
// takes it at VISIBILITY_SAMPLES points spread over the step (their centres) and uses their mean.
const int VISIBILITY_SAMPLES = 4;

// The fraction of the step from `from` to `to` meters along the camera's ray that sees the sun.
float GetStepSunVisibility(ShadowRay ray, float from, float to) {
  float visible = 0.0;
  for (int i = 0; i < VISIBILITY_SAMPLES; ++i)
    visible += SunVisibilityOnRay(ray, mix(from, to, (float(i) + 0.5) / float(VISIBILITY_SAMPLES)));
  return visible / float(VISIBILITY_SAMPLES);
}

ShadowRay MakeCameraShadowRay(vec3 ray) { return MakeShadowRay(ray, AERIAL_FRAME.camera_planet_position.xyz); }

// GetSkyInscatterToPoint (sky_lookup.glsl) along the camera's unit ray `ray`, each step's single
// scattering scaled by the fraction of it that sees the sun.
Inscatter GetShadowedSkyInscatterToPoint(sampler2D transmittance_texture, sampler3D multiple_density_texture,
                                         vec3 ray, float r, float mu, float mu_s, float nu, float d) {
  InscatterMarch march = StartInscatterMarch(transmittance_texture, multiple_density_texture, r, mu, mu_s, nu);
  d = min(d, DistanceToNearestAtmosphereBoundary(r, mu, march.ray_r_mu_intersects_ground));
  ShadowRay shadow_ray = MakeCameraShadowRay(ray);
  float previous = 0.0;
  for (int i = 1; i <= SEGMENT_STEPS; ++i) {
    float distance = d * float(i) / float(SEGMENT_STEPS);
    AdvanceInscatterMarch(transmittance_texture, multiple_density_texture, march, distance,
                          GetStepSunVisibility(shadow_ray, previous, distance));
    previous = distance;
  }
  return GetInscatterMarchResult(march);
}

#endif
