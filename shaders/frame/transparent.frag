#version 450
#extension GL_GOOGLE_include_directive : require
// Transparent geometry: the surface lit per vertex (transparent.vert), its sun part times the
// sun's visibility here (shadow.glsl: opaque casters shade glass too), seen through the
// interpolated per-vertex aerial perspective with per-pixel phase functions (or, in the
// per-pixel modes, the tables), output premultiplied: alpha (L T + I_R P_R + I_M P_M) over what
// is already drawn. What is drawn already holds the inscatter of the segment in front of the surface, so
// this blend is exact: I + T (alpha L + (1 - alpha) L_behind).
#include "mesh_tables.glsl"
#include "surface.glsl"
#define AERIAL_SHADOW_BINDING 8
#include "shadow.glsl"
layout(location = 0) in vec3 relative_position;
layout(location = 1) in vec4 sun_radiance_opacity;
layout(location = 2) in vec3 vertex_rayleigh;
layout(location = 3) in vec3 vertex_mie;
layout(location = 4) in vec3 vertex_transmittance;
layout(location = 5) in vec3 sky_radiance;
layout(location = 6) in vec3 facing_normal;
layout(location = 7) in vec3 shadow_coordinates[kShadowCascades];
layout(location = 0) out vec4 color;

void main() {
  float distance = length(relative_position);
  vec3 ray = relative_position / distance;
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  Inscatter segment;
  if (kAerialPerPixel != AERIAL_FROXELS) {
    segment = GetMeshAerialPerspectivePerPixel(ray, r, mu, mu_s, nu, distance);
  } else {
    segment.rayleigh = vertex_rayleigh;
    segment.mie = vertex_mie;
    segment.transmittance = vertex_transmittance;
  }
  float alpha = sun_radiance_opacity.a;
  vec3 normal = normalize(facing_normal);
  vec3 surface_radiance = ShadeLambertian(LambertianRadiance(sun_radiance_opacity.rgb, sky_radiance), normal,
                                          SunVisibilityFromCoordinates(relative_position, shadow_coordinates));
  vec3 radiance = ApplyAerialPerspective(surface_radiance, segment, nu);
  color = vec4(radiance * alpha, alpha);
}
