// The sky-view table (Hillaire 2020, "sky-view LUT"): per frame, the Rayleigh and Mie inscatter
// and the transmittance of the whole view ray, for every direction around the camera, so that sky
// pixels read 2 taps instead of evaluating the 4D lookups (sky_view.comp). Directions are (azimuth
// from the sun's vertical plane, zenith angle); the sky is symmetric about that plane, so the
// azimuth covers [0, pi]. The zenith axis is split at the horizon like the scattering tables' mu
// axis, each half on its own texel centers, with the square-root mapping of Hillaire 2020 that
// puts most rows next to the horizon, where the sky changes fastest.
#ifndef AERIAL_SKY_VIEW_GLSL
#define AERIAL_SKY_VIEW_GLSL
#include "frame.glsl"
#include "mappings.glsl"
#include "sky_view_lattice.glsl"

// (u, v) of a direction: cos_phi relative to the sun's azimuth, theta the zenith angle, theta_h
// the horizon's (HorizonZenithAngle of the camera's r: the same for every direction of a frame).
vec2 GetSkyViewUv(float theta_h, float cos_phi, float theta, ivec2 size) {
  float v;
  if (theta < theta_h) {
    float x = 1.0 - sqrt(max(1.0 - theta / theta_h, 0.0));  // 0 at the zenith, 1 at the horizon
    v = 0.5 * GetTextureCoordFromUnitRange(x, size.y / 2);
  } else {
    float x = sqrt(clamp((theta - theta_h) / (PI - theta_h), 0.0, 1.0));  // 0 at the horizon
    v = 0.5 + 0.5 * GetTextureCoordFromUnitRange(x, size.y / 2);
  }
  float u = GetTextureCoordFromUnitRange(acos(clamp(cos_phi, -1.0, 1.0)) / PI, size.x);
  return vec2(u, v);
}

// (u, v) of a unit view ray whose cosine with the camera's up is mu, in the camera's local frame
// (GetSkyViewFrame: up, toward_sun) with its horizon's zenith angle theta_h.
vec2 GetSkyViewUvOfRay(vec3 ray, float mu, vec3 up, vec3 toward_sun, float theta_h, ivec2 size) {
  vec3 horizontal = ray - mu * up;
  float cos_phi = dot(horizontal, horizontal) > 1e-12 ? dot(normalize(horizontal), toward_sun) : 1.0;
  return GetSkyViewUv(theta_h, cos_phi, acos(clamp(mu, -1.0, 1.0)), size);
}

// The inverse, for the texels of the table: returns (cos_phi, theta).
vec2 GetSkyViewDirection(float r, vec2 uv, ivec2 size) {
  float theta_h = HorizonZenithAngle(r);
  float theta;
  if (uv.y < 0.5) {
    float x = GetUnitRangeFromTextureCoord(2.0 * uv.y, size.y / 2);
    float s = 1.0 - x;
    theta = theta_h * (1.0 - s * s);
  } else {
    float x = GetUnitRangeFromTextureCoord(2.0 * uv.y - 1.0, size.y / 2);
    theta = theta_h + (PI - theta_h) * x * x;
  }
  float phi = PI * GetUnitRangeFromTextureCoord(uv.x, size.x);
  return vec2(cos(phi), theta);
}

// The world-space basis of the camera's local frame: up, and the horizontal direction toward the
// sun (any horizontal direction when the sun is at the zenith).
void GetSkyViewFrame(out vec3 up, out vec3 toward_sun, out vec3 side) {
  up = normalize(AERIAL_FRAME.camera_planet_position.xyz);
  vec3 sun = AERIAL_FRAME.sun_direction.xyz;
  vec3 horizontal = sun - dot(sun, up) * up;
  toward_sun = dot(horizontal, horizontal) > 1e-12
                   ? normalize(horizontal)
                   : normalize(cross(up, abs(up.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0)));
  side = cross(up, toward_sun);
}

// A view ray of the table: through texel `texel` of a table of `size`, in world space, with its
// (r, mu, mu_s, nu) at the camera.
struct SkyViewRay {
  vec3 direction;
  float r, mu, mu_s, nu;
};

SkyViewRay GetSkyViewRay(ivec2 texel, ivec2 size) {
  SkyViewRay ray;
  ray.r = length(AERIAL_FRAME.camera_planet_position.xyz);
  vec2 angles = GetSkyViewDirection(ray.r, (vec2(texel) + 0.5) / vec2(size), size);
  vec3 up, toward_sun, side;
  GetSkyViewFrame(up, toward_sun, side);
  float sin_theta = sin(angles.y);
  ray.direction = up * cos(angles.y) +
                  sin_theta * (toward_sun * angles.x + side * sqrt(max(1.0 - angles.x * angles.x, 0.0)));
  ray.mu = dot(up, ray.direction);
  ray.mu_s = dot(up, AERIAL_FRAME.sun_direction.xyz);
  ray.nu = dot(ray.direction, AERIAL_FRAME.sun_direction.xyz);
  return ray;
}

#endif
