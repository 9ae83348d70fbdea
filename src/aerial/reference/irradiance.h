#pragma once
// Irradiance on a horizontal surface at radius r.
//  - Direct: E_0 = E_sun T(r, mu_s -> top) c(mu_s), with c Bruneton 2017's average cosine of the
//    solar disc (SunAverageCosine; ComputeDirectIrradiance). No planet-shadow factor: c already
//    fades the sun out over the disc's angular radius around mu_s = 0.
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
