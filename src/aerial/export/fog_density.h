#pragma once
// The `density` grid: the air's extinction coefficient at a voxel's center, one scalar in 1/m,
// what Houdini and Blender take as a fog volume's density (1 unit = 1 m). Per channel c, at the
// altitude h of the point above the planet sphere, in the atmosphere the froxels were computed
// with (Bruneton 2017's model: each constituent's coefficient at density 1 times its profile):
//   sigma_c(h) = rayleigh_scattering_c rho_R(h) + mie_extinction_c rho_M(h)
//                + absorption_extinction_c rho_O(h)
// and the scalar weighs the channels as inscatter_luminance does (Rec. 709 luma):
//   density = 0.2126 sigma_R + 0.7152 sigma_G + 0.0722 sigma_B
// The air spans the altitudes 0 to top - bottom radius, as in the renderer: above the top there
// is none (density 0), and below sea level (a valley of the terrain) the air is sea level's (the
// shaders clamp radii to the planet's; the profiles themselves would give 0 there).
// It is the rate at which the optical depth -ln T of the froxels' transmittance grows along a
// view ray. Taken from that transmittance instead, as ln(T(s0) / T(s1)) / (s1 - s0) over each
// voxel's segment of its ray, it agreed to 1.4% at the median but was off by 40% or more on a
// tenth of the frustum grid's voxels and not positive on some (the test scene, full tables):
// T comes from ratios of a tabulated transmittance, whose interpolation errors swamp its
// derivative.
#include <glm/glm.hpp>

#include "aerial/atmosphere.h"

namespace aerial {

// 0.2126 R + 0.7152 G + 0.0722 B of the (680, 550, 440 nm) channels.
double Luma(const glm::dvec3& rgb);

// The air's coefficients per channel at a point, in 1/m, what a path tracer's volume shader takes
// (Houdini's Karma Volume, MaterialX's anisotropic_vdf, Blender's Volume Scatter and Absorption):
//   scattering_c = rayleigh_scattering_c rho_R(h) + mie_scattering_c rho_M(h)
//   absorption_c = (mie_extinction_c - mie_scattering_c) rho_M(h) + absorption_extinction_c rho_O(h)
// at the altitudes below, so that scattering + absorption is the sigma above.
struct AirCoefficients {
  glm::dvec3 scattering, absorption;
};
AirCoefficients AirCoefficientsAt(const AtmosphereParameters& atmosphere, const glm::dvec3& point);

// The density above at a world point (scene frame, m: the planet's center at (0, 0, -R)).
double FogDensity(const AtmosphereParameters& atmosphere, const glm::dvec3& point);

}  // namespace aerial
