#pragma once
// Irradiance on a horizontal surface at radius r.
//  - Direct: E_0 = E_sun <V T max(mu, 0)>_disc, the disc's visible part, each through its own
//    slant of the atmosphere (solar_disc.h).
//  - Sky: E_sky = sum_{j=1..M} int_{upper hemisphere} L_j(x, w) cos(w) dw (Bruneton 2017's
//    ComputeIndirectIrradiance),
//    L_j the radiance of order j, estimated by the path tracer from cosine-sampled directions.
#include "aerial/reference/medium.h"
#include "aerial/reference/monte_carlo.h"

namespace aerial::reference {

Spectrum ComputeDirectIrradiance(const Medium& medium, Accuracy accuracy, double r, double mu_s);

// Orders 1..max_order of the sky irradiance, each with its standard error.
OrderEstimates EstimateSkyIrradianceOrders(const Medium& medium, double r, double mu_s,
                                           int max_order, const MonteCarloOptions& options);

}  // namespace aerial::reference
