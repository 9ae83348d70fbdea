#pragma once
// Sunlight from the whole solar disc. The sun is a uniform disc of angular radius alpha; a point of
// it at elevation y alpha above the disc centre (y in [-1, 1]) has zenith angle theta_s - y alpha,
// and the disc's area at elevation y has the chord density (2 / pi) sqrt(1 - y^2). Each part of the
// disc reaches radius r through its own slant of the atmosphere and only if it is above the
// horizon, so the light averaged over the disc is
//   <g> = integral_{-1}^{1} (2 / pi) sqrt(1 - y^2) V(mu(y)) g(mu(y)) dy,  mu(y) = cos(theta_s - y alpha),
// V = 1 above the horizon zenith cosine -sqrt(1 - (R / r)^2), else 0. With y = cos t this is
// (2 / pi) times the integral over t in [0, t_h] of sin^2 t g(cos(theta_s - alpha cos t)), t_h the
// horizon's t, a smooth integrand that Gauss-Legendre integrates to ~1e-12 (solar_disc_test).
// The flat-disc chord density is exact to O(alpha^2) ~ 2e-5 relative.
//
// This replaces, in the reference, the product of the centre's transmittance and the visible
// fraction of the disc (the shaders' approximation, GetTransmittanceToSun) and Bruneton 2017's
// average cosine of the disc over a horizontal surface.
#include "aerial/reference/medium.h"
#include "aerial/reference/monte_carlo_chunks.h"
#include "aerial/reference/wavelength_groups.h"

namespace aerial::reference {

// <V T>: the disc-averaged transmittance to radius r of sunlight whose disc centre has zenith
// cosine mu_s (E_sun times this is the sun's irradiance normal to the sun at r).
Spectrum SunDiscTransmittance(const Medium& medium, Accuracy accuracy, double r, double mu_s);

// <V T max(mu, 0)>: E_sun times this is the sun's irradiance on a horizontal surface at r.
Spectrum SunDiscHorizontalIrradianceFactor(const Medium& medium, Accuracy accuracy, double r,
                                           double mu_s);

// One-sample estimates of the same at every wavelength of `groups`, for the path tracer's
// next-event estimates (kMonteCarlo columns): a point drawn uniformly over the disc's area (its y
// then has the chord density), through its own slant, 0 below the horizon. Unbiased, and one slant
// where the quadrature takes 3 to 32 near the horizon; the mean of many paths does the
// quadrature's work. Where the centre's slant is the disc's (more than 20 degrees up) it is used
// and draws nothing from rng.
Channels SampleSunDiscTransmittance(const WavelengthGroups& groups, double r, double mu_s, Rng& rng);
Channels SampleSunDiscHorizontalIrradianceFactor(const WavelengthGroups& groups, double r, double mu_s, Rng& rng);

}  // namespace aerial::reference
