#pragma once
// Which wavelengths of a spectral precompute get all their scattering orders, and how the others
// get their orders >= 2 (docs/colour.md, "Higher orders at every other wavelength").
//
// Single scattering carries the sharp spectral detail of a sky: it is computed at every
// wavelength. The orders >= 2 are computed at every other wavelength, and in between they are read
// from their neighbours. Per unit of sunlight, a light path's response is exp(-optical depth)
// times its scattering coefficients: the scattering goes as a power of lambda (lambda^-4 for
// Rayleigh, Angstrom's law for Mie) and the ozone's absorption is the one spectrum that is not
// smooth (the Chappuis band). So log(higher orders / sunlight) is fitted over the two neighbours
// on each side by 1, log(lambda) and the ozone's absorption coefficient, by least squares, and the
// fit is read at the wavelength. The weights depend on the wavelengths only: one set per
// wavelength, applied to every texel.
#include <vector>

#include "aerial/spectrum/spectral_atmosphere.h"
#include "aerial/spectrum/spectral_sampling.h"

namespace aerial::spectrum {

// Every other wavelength, from the first: with 12, 380 to 771 nm; 810 nm, where the observer sees
// almost nothing, is read from the two below it.
inline bool HasAllOrders(int wavelength_index) { return wavelength_index % 2 == 0; }

// How one wavelength's higher orders are made: log(value / sun) = sum_j weights[j] log(value_j /
// sun_j) over the wavelengths `from` (itself alone, weight 1, where it has all orders).
struct HigherOrderStencil {
  std::vector<int> from;
  std::vector<double> weights;
};

// One stencil per wavelength of `sampling`.
std::vector<HigherOrderStencil> HigherOrderStencils(const SpectralSampling& sampling,
                                                    const SpectralAtmosphere& atmosphere);

// Weights w_j such that sum_j w_j y_j is the least-squares fit of the values y_j by the basis
// functions, read where the functions take the values `at`. basis[j][k]: function k at point j.
// With as many functions as points, the fit interpolates.
std::vector<double> LeastSquaresWeights(const std::vector<std::vector<double>>& basis,
                                        const std::vector<double>& at);

}  // namespace aerial::spectrum
