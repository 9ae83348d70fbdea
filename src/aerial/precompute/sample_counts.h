// The precompute's integration sample counts, derived from the public PrecomputeOptions (they are
// not options of their own: the density tables follow the scattering tables' size, and Small()'s
// coarse direction grid is PrecomputeOptions::coarse_directions).
#pragma once

#include "aerial/table_options.h"

namespace aerial {

// Bruneton 2017 uses 500, 50, 32x64 and a 16x32 density grid.
struct SampleCounts {
  int transmittance_steps = 500;
  int ray_steps = 50;  // single scattering, per ray
  // Multiple scattering is a smooth fraction of the sky (20-40% in daylight) and its steps are
  // integrated exponentially: 32 steps change the 4-order sky by at most 0.28% against 200
  // (measured over six views from the ground to 50 km, low sun included).
  int multiple_scattering_steps = 32;
  int irradiance_zenith = 32;
  int irradiance_azimuth = 32;  // over [0, pi], mirrored (Bruneton: 64 over [0, 2 pi])
  int density_theta_up = 16;    // density grid: zenith cells above the horizon
  int density_theta_down = 8;   // zenith cells below the horizon
  int density_phi = 16;         // azimuth cells over [0, pi] (mirrored to [0, 2 pi])
  // Resolution of the per-order scattering density and multiple scattering tables. Both are
  // smooth (the density is a convolution with the phase functions), so they take the scattering
  // table's r, mu_s and nu and half its mu; the Rayleigh table receives them resampled at full
  // resolution.
  int density_r = 32;
  int density_mu = 64;
  int density_mu_s = 36;
  int density_nu = 9;
};

SampleCounts SampleCountsOf(const PrecomputeOptions& options);

}  // namespace aerial
