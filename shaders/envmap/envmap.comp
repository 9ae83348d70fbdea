#version 450
#extension GL_GOOGLE_include_directive : require
// An environment map: the sky seen from one point in the direction of each texel, as aerial's
// sky pass draws it per pixel (GetSkyRadianceAlongRay, aerial_perspective.glsl): the inscatter
// with the direction's own phase functions and, where the direction meets the planet, the lit
// bare ground through the air. The phase-free parts come from envmap_lattice.comp's lattice,
// linear in the azimuth from the sun's vertical plane and, unless the lattice's rows are the
// image's (a lat-long map), in the zenith angle on the texel's side of the horizon. The sun's
// disc is drawn only when asked for, each texel it touches getting the disc's radiance times the
// part of the texel it covers (sampled 16x16), so that the map holds the sun's whole irradiance at
// any resolution; invocation 0 also writes the sun's irradiance at the point, normal to its rays.
#include "aerial_perspective.glsl"
#include "sky_view.glsl"
layout(local_size_x = 64) in;
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
// World directions (x east, y north, z up) of the texels' centres, row-major, top row first; the
// image is a stack of faces of face_height rows each (one for a lat-long map, six for a cube).
layout(std430, set = 0, binding = 3) readonly buffer Directions { vec4 directions[]; };
layout(std430, set = 0, binding = 4) readonly buffer Lattice { vec4 nodes[]; };
layout(std430, set = 0, binding = 5) writeonly buffer Radiance { vec4 radiance[]; };
layout(std430, set = 0, binding = 6) writeonly buffer Sunlight { vec4 sun_irradiance; };
layout(push_constant) uniform Map {
  int width;
  int height;
  int face_height;
  int sun_disc;       // 1: the disc in the map
  int azimuths;       // the lattice's azimuth nodes over [0, pi]
  int rows_above;     // 0: the lattice's rows are the image's; else its rows above the horizon
  int rows_below;     // and below it, each side's spaced evenly in zenith angle from ...
  float zenith_above; // ... 0 to this, and from zenith_below to pi
  float zenith_below;
} map;

const int DISC_SAMPLES = 16;  // per texel side, where the disc may touch the texel

vec3 TexelDirection(int x, int y) { return directions[y * map.width + x].xyz; }

// The texel's extent as two direction differences: to the next texel across and down, within its
// face (backward at the face's last column or row).
void GetTexelSpan(int x, int y, vec3 center, out vec3 across, out vec3 down) {
  across = x + 1 < map.width ? TexelDirection(x + 1, y) - center : center - TexelDirection(x - 1, y);
  down = (y + 1) % map.face_height != 0 ? TexelDirection(x, y + 1) - center : center - TexelDirection(x, y - 1);
}

// The sun disc's radiance through the air (ShadeBackground of the sky pass) averaged over the texel.
vec3 GetSunDiscOverTexel(vec3 center, vec3 across, vec3 down, vec3 transmittance) {
  float reach = AERIAL_ATMOSPHERE.sun_angular_radius + length(across) + length(down);
  if (dot(center, AERIAL_FRAME.sun_direction.xyz) < cos(reach)) return vec3(0.0);
  vec3 sum = vec3(0.0);
  for (int j = 0; j < DISC_SAMPLES; ++j) {
    for (int i = 0; i < DISC_SAMPLES; ++i) {
      vec2 offset = (vec2(i, j) + 0.5) / float(DISC_SAMPLES) - 0.5;
      vec3 ray = normalize(center + offset.x * across + offset.y * down);
      sum += ShadeBackground(transmittance, false, ray);
    }
  }
  return sum / float(DISC_SAMPLES * DISC_SAMPLES);
}

// Node k (0 rayleigh, 1 mie, 2 behind) of the lattice at a fractional row and azimuth node.
vec3 ReadLattice(float row, float azimuth, int k) {
  int row0 = int(floor(row)), azimuth0 = min(int(floor(azimuth)), map.azimuths - 2);
  int row1 = min(row0 + 1, map.rows_above + map.rows_below - 1);
  if (map.rows_above == 0) row1 = row0;
  float a = azimuth - float(azimuth0), b = row - float(row0);
  vec3 lower = mix(nodes[3 * (row0 * map.azimuths + azimuth0) + k].xyz,
                   nodes[3 * (row0 * map.azimuths + azimuth0 + 1) + k].xyz, a);
  vec3 upper = mix(nodes[3 * (row1 * map.azimuths + azimuth0) + k].xyz,
                   nodes[3 * (row1 * map.azimuths + azimuth0 + 1) + k].xyz, a);
  return mix(lower, upper, b);
}

void main() {
  int x = int(gl_GlobalInvocationID.x), y = int(gl_GlobalInvocationID.y);
  float r, mu, mu_s, nu;
  if (x == 0 && y == 0) {
    GetCameraRayParameters(AERIAL_FRAME.sun_direction.xyz, r, mu, mu_s, nu);
    sun_irradiance = vec4(GetDirectSunlight(transmittance_texture, r, mu_s, GetHorizonCosine(r), false), 0.0);
  }
  if (x >= map.width || y >= map.height) return;
  vec3 ray = TexelDirection(x, y);
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  bool ground = RayIntersectsGround(r, mu);
  vec3 up, toward_sun, side;
  GetSkyViewFrame(up, toward_sun, side);
  vec3 horizontal = ray - mu * up;
  float cos_phi = dot(horizontal, horizontal) > 1e-12 ? dot(normalize(horizontal), toward_sun) : 1.0;
  float azimuth = acos(clamp(cos_phi, -1.0, 1.0)) / PI * float(map.azimuths - 1);
  float row;
  if (map.rows_above == 0) {
    row = float(y);
  } else {
    float theta = acos(clamp(mu, -1.0, 1.0));
    row = ground ? float(map.rows_above) + clamp((theta - map.zenith_below) / (PI - map.zenith_below), 0.0, 1.0) *
                                               float(map.rows_below - 1)
                 : clamp(theta / map.zenith_above, 0.0, 1.0) * float(map.rows_above - 1);
    // Never across the horizon: the last row above blends with nothing below it.
    if (!ground) row = min(row, float(map.rows_above - 1) - 1e-4);
  }
  Inscatter sky;
  sky.rayleigh = ReadLattice(row, azimuth, 0);
  sky.mie = ReadLattice(row, azimuth, 1);
  vec3 behind = ReadLattice(row, azimuth, 2);
  vec3 color = ApplyPhaseFunctions(sky, nu);
  if (ground) {
    color += behind;
  } else if (map.sun_disc != 0) {
    vec3 across, down;
    GetTexelSpan(x, y, ray, across, down);
    color += GetSunDiscOverTexel(ray, across, down, behind);
  }
  radiance[y * map.width + x] = vec4(color, 1.0);
}
