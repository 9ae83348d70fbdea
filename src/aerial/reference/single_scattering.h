#pragma once
// Single scattering by deterministic adaptive quadrature along the view ray, without the phase
// functions and per species as in Bruneton 2017's ComputeSingleScattering(Integrand):
//   S_R = int_0^D T(x, p) beta_R rho_R(p) T_sun(p) f(p) E_sun ds,  S_M likewise with beta_M,sca,
// where T_sun is the transmittance from p to the top towards the sun's centre and f the visible
// fraction of the solar disc (geometry.h). The integrand has kinks where the ray crosses a
// density level and where it enters the Earth's penumbra (f = 0 or 1); both are breakpoints of the
// adaptive Gauss-Kronrod integration.
#include "aerial/reference/medium.h"

namespace aerial::reference {

struct SingleScattering {
  Spectrum rayleigh{};  // W/m^2/nm; times a phase function (1/sr) gives radiance.
  Spectrum mie{};
};

// Over [0, length] of the view ray from radius r with cosines mu (view zenith), mu_s (sun zenith)
// and nu (view-sun). length must not exceed the distance to the ground or the top.
// rel_tol bounds the summed Gauss-Kronrod error estimates relative to each component.
SingleScattering ComputeSingleScattering(const Medium& medium, double r, double mu, double mu_s,
                                         double nu, double length, double rel_tol = 1e-7);

}  // namespace aerial::reference
