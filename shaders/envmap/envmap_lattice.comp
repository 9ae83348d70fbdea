#version 450
#extension GL_GOOGLE_include_directive : require
// The costly part of an environment map, on a lattice: for each row's zenith angle and each
// azimuth from the sun's vertical plane (azimuth nodes over [0, pi]: the sky is symmetric about
// that plane), the tables' phase-free inscatter (GetSkyInscatter, as `aerial probe` reads it)
// and what lies behind it: where the direction meets the planet the lit bare ground through the
// air (GetBackgroundThroughAtmosphere), else the transmittance. envmap.comp interpolates it in
// azimuth (and for a cube map in zenith) and applies each texel's own phase functions.
#include "aerial_perspective.glsl"
#include "sky_view.glsl"
layout(local_size_x = 64) in;
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler2D irradiance_texture;
layout(std430, set = 0, binding = 7) readonly buffer Rows { float row_zenith[]; };
// Per node, row-major (azimuth fastest): rayleigh, mie, behind.
layout(std430, set = 0, binding = 8) writeonly buffer Lattice { vec4 nodes[]; };
layout(push_constant) uniform Shape {
  int rows;
  int azimuths;  // nodes over [0, pi], both ends included
} shape;

void main() {
  int j = int(gl_GlobalInvocationID.x), i = int(gl_GlobalInvocationID.y);
  if (j >= shape.azimuths || i >= shape.rows) return;
  vec3 up, toward_sun, side;
  GetSkyViewFrame(up, toward_sun, side);
  float theta = row_zenith[i], phi = PI * float(j) / float(shape.azimuths - 1);
  vec3 ray = up * cos(theta) + sin(theta) * (toward_sun * cos(phi) + side * sin(phi));
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  Inscatter sky = GetSkyInscatter(transmittance_texture, rayleigh_texture, mie_texture, multiple_texture, r, mu,
                                  mu_s, nu);
  vec3 behind = GetBackgroundThroughAtmosphere(transmittance_texture, irradiance_texture, ray, r, mu, sky.transmittance);
  int node = 3 * (i * shape.azimuths + j);
  nodes[node] = vec4(sky.rayleigh, 0.0);
  nodes[node + 1] = vec4(sky.mie, 0.0);
  nodes[node + 2] = vec4(behind, 0.0);
}
