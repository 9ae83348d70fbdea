// Inscatter over a segment of a view ray, integrated along the segment at render time instead of
// read as the difference of two table values, S(x, v) - T(x, p) S(p, v) (Bruneton 2008 eq. 16).
// The difference cancels where the segment holds a small part of the whole ray's inscatter: 10 km
// of a ray from a camera 50 km up that goes on to the ground, or a low sun whose shadow line
// crosses the ray. Each table value is good to about 1%, the difference then to tens of percent
// (measured against the reference, docs/accuracy.md, "Radiance to a point").
//  - Single scattering: Bruneton 2008 eq. 11 over the segment, with the sun's transmittance from
//    the table (the Earth's shadow exactly where the ray passes, in the 4D variant).
//  - Multiple scattering: the scattering density of orders >= 2, J_ms (the multiple density table),
//    attenuated back to the camera: Bruneton 2008 eq. 12 over the segment, all orders at once.
// The march is incremental, so that the froxel pass integrates a whole column in one walk, and
// each step takes the fraction of it from which the sun is visible (shadow.glsl), which scales
// its single scattering: shadowed in-scattering (light shafts, mountain shadows in the air).
// Multiple scattering is left unshadowed: it arrives from the whole sky, and an occluder of a few
// km hides the sun, not the sky, from the air behind it.
#ifndef AERIAL_INSCATTER_MARCH_GLSL
#define AERIAL_INSCATTER_MARCH_GLSL
#include "scattering.glsl"

// Inscatter of a segment or a whole ray, phases left to the caller (per pixel).
struct Inscatter {
  vec3 rayleigh;       // multiply by RayleighPhaseFunction(nu)
  vec3 mie;            // multiply by MiePhaseFunction(g, nu)
  vec3 transmittance;  // over the same segment
};

struct InscatterMarch {
  float r, mu, mu_s, nu;
  bool ray_r_mu_intersects_ground;
  vec3 origin;  // GetRayOpticalDepthOrigin of the ray
  vec3 ground_extinction;  // the air's extinction at the ground (ContinueInscatterMarchUnderGround)
  float distance;  // from the camera to the last sample
  vec3 transmittance;  // from the camera to the last sample
  // The integrands at the last sample: single scattering per unit of sunlight and scattering
  // coefficient (ComputeSingleScatteringIntegrandAt), and attenuated J_ms.
  vec3 rayleigh_integrand, mie_integrand, multiple_integrand;
  // Their integrals from the camera to the last sample.
  vec3 rayleigh_sum, mie_sum, multiple_sum;
};

void SampleInscatterIntegrands(sampler2D transmittance_texture, sampler3D multiple_density_texture,
                               inout InscatterMarch march, float d) {
  float r_d = RadiusAtDistance(march.r, march.mu, d);
  float mu_d = MuAtDistance(march.r, march.mu, d, r_d);
  float mu_s_d = SunCosineAlongRay(march.r, march.mu_s, march.nu, d, r_d);
  march.distance = d;
  vec3 view = GetOpticalDepthFromOrigin(transmittance_texture, march.origin, march.r, march.mu, d,
                                        march.ray_r_mu_intersects_ground);
  march.transmittance = exp(-view);
  ComputeSingleScatteringIntegrandAt(r_d, GetSunlightAt(transmittance_texture, r_d, mu_s_d, view),
                                     march.rayleigh_integrand, march.mie_integrand);
  march.multiple_integrand =
      march.transmittance * GetMultipleScatteringDensity(multiple_density_texture, r_d, mu_d,
                                                         mu_s_d, march.nu,
                                                         march.ray_r_mu_intersects_ground);
}

// A march of the view ray (r, mu) with the sun at (mu_s, nu), at the camera.
InscatterMarch StartInscatterMarch(sampler2D transmittance_texture,
                                   sampler3D multiple_density_texture, float r, float mu,
                                   float mu_s, float nu) {
  InscatterMarch march;
  march.r = r;
  march.mu = mu;
  march.mu_s = mu_s;
  march.nu = nu;
  march.ray_r_mu_intersects_ground = RayIntersectsGround(r, mu);
  march.origin = GetRayOpticalDepthOrigin(transmittance_texture, r, mu,
                                          march.ray_r_mu_intersects_ground);
  march.ground_extinction = GetExtinction(AERIAL_ATMOSPHERE.bottom_radius);
  march.rayleigh_sum = vec3(0.0);
  march.mie_sum = vec3(0.0);
  march.multiple_sum = vec3(0.0);
  SampleInscatterIntegrands(transmittance_texture, multiple_density_texture, march, 0.0);
  return march;
}

// Beyond the ground the march goes on in air as it is at the ground point: each integrand keeps
// its value there, attenuated by the ground's extinction over the distance gone under it. The
// froxels need it: a pixel below the horizon reads the rows above and below its own, and the
// lower row's ray meets the ground nearer than the pixel's surface. Held at the ground point's
// value, that row's slices beyond it would give the pixel the inscatter of a shorter segment,
// darkening the ground a few km away under a low sun.
void ContinueInscatterMarchUnderGround(inout InscatterMarch march, float d, float sun_visibility) {
  float dx = d - march.distance;
  if (dx <= 0.0) return;
  vec3 attenuation = exp(-march.ground_extinction * dx);
  // The integral over [0, dx] of exp(-extinction s).
  vec3 length_attenuated = (1.0 - attenuation) / max(march.ground_extinction, vec3(1e-30));
  march.rayleigh_sum += march.rayleigh_integrand * length_attenuated * sun_visibility;
  march.mie_sum += march.mie_integrand * length_attenuated * sun_visibility;
  march.multiple_sum += march.multiple_integrand * length_attenuated;
  march.rayleigh_integrand *= attenuation;
  march.mie_integrand *= attenuation;
  march.multiple_integrand *= attenuation;
  march.transmittance *= attenuation;
  march.distance = d;
}

// Moves the march to distance d, integrating the step with ExponentialStepIntegral up to the
// atmosphere's boundary and on under the ground beyond it (ContinueInscatterMarchUnderGround);
// sun_visibility: the fraction of the step that sees the sun.
void AdvanceInscatterMarch(sampler2D transmittance_texture, sampler3D multiple_density_texture,
                           inout InscatterMarch march, float d, float sun_visibility) {
  float boundary = DistanceToNearestAtmosphereBoundary(march.r, march.mu,
                                                       march.ray_r_mu_intersects_ground);
  float in_air = min(d, boundary);
  float dx = in_air - march.distance;
  if (dx > 0.0) {
    vec3 rayleigh_previous = march.rayleigh_integrand;
    vec3 mie_previous = march.mie_integrand;
    vec3 multiple_previous = march.multiple_integrand;
    SampleInscatterIntegrands(transmittance_texture, multiple_density_texture, march, in_air);
    float lit = sun_visibility * dx;
    march.rayleigh_sum += ExponentialStepIntegral(rayleigh_previous, march.rayleigh_integrand) * lit;
    march.mie_sum += ExponentialStepIntegral(mie_previous, march.mie_integrand) * lit;
    march.multiple_sum +=
        ExponentialStepIntegral(multiple_previous, march.multiple_integrand) * dx;
  }
  if (march.ray_r_mu_intersects_ground) ContinueInscatterMarchUnderGround(march, d, sun_visibility);
}

// The march's inscatter so far, without phase: multiple scattering (phase included in J_ms) goes
// to the Rayleigh part divided by P_R(nu), which the caller's product restores (nu is the same
// along the ray, so this is exact).
Inscatter GetInscatterMarchResult(InscatterMarch march) {
  vec3 sun = AERIAL_ATMOSPHERE.solar_irradiance.rgb;
  Inscatter result;
  result.rayleigh = march.rayleigh_sum * sun * AERIAL_ATMOSPHERE.rayleigh_scattering.rgb +
                    march.multiple_sum / RayleighPhaseFunction(march.nu);
  result.mie = march.mie_sum * sun * AERIAL_ATMOSPHERE.mie_scattering.rgb;
  result.transmittance = march.transmittance;
  return result;
}

#endif
