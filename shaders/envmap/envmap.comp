#version 450
#extension GL_GOOGLE_include_directive : require
// An environment map: the sky seen from one point in the direction of each texel, as aerial's
// sky pass draws it per pixel (GetSkyRadianceAlongRay, aerial_perspective.glsl): the tables'
// inscatter with the direction's own phase functions and, where the direction meets the planet,
// the lit bare ground through the air. The sun's disc is drawn only when asked for, each texel it
// touches getting the disc's radiance times the part of the texel it covers (sampled 16x16), so
// that the map holds the sun's whole irradiance at any resolution; invocation 0 also writes the
// sun's irradiance at the point, normal to its rays, for a separate sun lamp.
#include "aerial_perspective.glsl"
layout(local_size_x = 64) in;
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler2D irradiance_texture;
// World directions (x east, y north, z up) of the texels' centres, row-major, top row first; the
// image is a stack of faces of face_height rows each (one for a lat-long map, six for a cube).
layout(std430, set = 0, binding = 7) readonly buffer Directions { vec4 directions[]; };
layout(std430, set = 0, binding = 8) writeonly buffer Radiance { vec4 radiance[]; };
layout(std430, set = 0, binding = 9) writeonly buffer Sunlight { vec4 sun_irradiance; };
layout(push_constant) uniform Map {
  int width;
  int height;
  int face_height;
  int sun_disc;  // 1: the disc in the map
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
  float reach = atmosphere.sun_angular_radius + length(across) + length(down);
  if (dot(center, frame.sun_direction.xyz) < cos(reach)) return vec3(0.0);
  vec3 sum = vec3(0.0);
  for (int j = 0; j < DISC_SAMPLES; ++j) {
    for (int i = 0; i < DISC_SAMPLES; ++i) {
      vec2 offset = (vec2(i, j) + 0.5) / float(DISC_SAMPLES) - 0.5;
      vec3 ray = normalize(center + offset.x * across + offset.y * down);
      sum += ShadeBackground(transmittance, false, dot(ray, frame.sun_direction.xyz));
    }
  }
  return sum / float(DISC_SAMPLES * DISC_SAMPLES);
}

void main() {
  int x = int(gl_GlobalInvocationID.x), y = int(gl_GlobalInvocationID.y);
  float r, mu, mu_s, nu;
  if (x == 0 && y == 0) {
    GetCameraRayParameters(frame.sun_direction.xyz, r, mu, mu_s, nu);
    sun_irradiance = vec4(GetDirectSunlight(GetSunLightAt(transmittance_texture, r, mu_s)), 0.0);
  }
  if (x >= map.width || y >= map.height) return;
  vec3 ray = TexelDirection(x, y);
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  Inscatter sky = GetSkyInscatter(transmittance_texture, rayleigh_texture, mie_texture, multiple_texture, r, mu,
                                  mu_s, nu);
  vec3 color = ApplyPhaseFunctions(sky, nu);
  if (RayIntersectsGround(r, mu)) {
    color += GetBackgroundThroughAtmosphere(transmittance_texture, irradiance_texture, ray, r, mu, sky.transmittance);
  } else if (map.sun_disc != 0) {
    vec3 across, down;
    GetTexelSpan(x, y, ray, across, down);
    color += GetSunDiscOverTexel(ray, across, down, sky.transmittance);
  }
  radiance[y * map.width + x] = vec4(color, 1.0);
}
