#pragma once
// Irradiance on a surface at radius r.
//  - Direct, horizontal surface: E_0 = E_sun <V T max(mu, 0)>_disc, the disc's visible part, each
//    through its own slant of the atmosphere (solar_disc.h).
//  - Sky: E_sky = sum_{j=1..M} int_{hemisphere about n} L_j(x, w) (n . w) dw (Bruneton 2017's
//    ComputeIndirectIrradiance for n up), L_j the radiance of order j, estimated by the path
//    tracer from cosine-sampled directions. A tilted normal's hemisphere dips below the horizon:
//    there it sees the ground (Lambertian, ground_albedo, lit by the sun and the sky) through the
//    air, a ground vertex of the path like any other.
#include "aerial/reference/medium.h"
#include "aerial/reference/monte_carlo_chunks.h"
#include "aerial/reference/wavelength_groups.h"

namespace aerial::reference {

Spectrum ComputeDirectIrradiance(const Medium& medium, Accuracy accuracy, double r, double mu_s);
// A one-sample estimate of it at every wavelength of `groups` (SampleSunDiscHorizontalIrradianceFactor).
Channels SampleDirectIrradiance(const WavelengthGroups& groups, double r, double mu_s, Rng& rng);

// Orders 1..max_order of the sky irradiance, each with its standard error, on a surface whose
// unit normal n has zenith cosine mu_n = n . up and cosine nu_n = n . sun to the sun (horizontal:
// mu_n = 1, nu_n = mu_s; nu_n must be feasible, see ClampNu).
// One estimate per group, from the same paths.
GroupOrderEstimates EstimateSkyIrradianceOrders(const WavelengthGroups& groups, double r, double mu_s,
                                                double mu_n, double nu_n, int max_order,
                                                        const MonteCarloOptions& options);
OrderEstimates EstimateSkyIrradianceOrders(const Medium& medium, double r, double mu_s, double mu_n,
                                           double nu_n, int max_order, const MonteCarloOptions& options);

}  // namespace aerial::reference
