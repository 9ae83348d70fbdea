// Aerial perspective for any surface shader: the contract that aerial's own opaque and transparent
// passes use and that a renderer embedding aerial includes in its shaders (installed to
// share/aerial/glsl). The froxel volume (froxel.glsl) holds, per froxel, the Rayleigh and Mie
// inscatter without phase and the transmittance from the camera; the phase functions are applied
// here, per pixel, from the pixel's own view ray, so that the sun's halo stays sharp at any froxel
// resolution. And the sky where no geometry is, from the tables.
//
// The caller binds, in set 0, the AtmosphereBlock at binding 0 (definitions.glsl) and the
// FrameBlock at binding 1 (frame.glsl), as aerial writes them (aerial::AtmosphereUniforms,
// aerial::FrameUniforms: their std140 layouts are checked against the GLSL compiler's in
// tests/uniform_layout_test.cpp), and passes the three froxel images as sampler3D (linear
// filtering, clamp to edge) wherever its own layout puts them. Positions are camera-relative
// world vectors (frame.glsl). The include declares specialization constant 0
// (kAerialPerPixel, frame.glsl: 0 reads the froxels, which is what a caller wants), so the
// caller's own constants start at 4 (aerial's passes use 1 to 4 in their own shaders).
//   Inscatter segment = GetAerialPerspective(rayleigh, mie, transmittance, gl_FragCoord.xy / frame.viewport.xy,
//                                            length(relative_position));
//   color.rgb = ApplyAerialPerspective(surface_radiance, segment, ViewSunCosine(relative_position));
//   sky.rgb = GetSkyRadianceAlongRay(transmittance, rayleigh, mie, multiple, irradiance, ray);
#ifndef AERIAL_AERIAL_PERSPECTIVE_GLSL
#define AERIAL_AERIAL_PERSPECTIVE_GLSL
#include "frame.glsl"
#include "froxel.glsl"
#include "surface.glsl"

// The segment from the camera to a point `distance` meters along the view ray through a screen
// position (uv in [0, 1]^2): per pixel, for opaque surfaces.
Inscatter GetAerialPerspective(sampler3D rayleigh_froxels, sampler3D mie_froxels, sampler3D transmittance_froxels,
                               vec2 screen_uv, float distance) {
  return SampleFroxels(rayleigh_froxels, mie_froxels, transmittance_froxels, screen_uv, distance,
                       float(AERIAL_FRAME.froxel_size.z), AERIAL_FRAME.froxel_depth.x, AERIAL_FRAME.froxel_columns,
                       AERIAL_FRAME.froxel_rows);
}

// The same read at a vertex from its clip-space position: per vertex, for transparent objects and
// particles, whose fragments then interpolate it (and still apply the phases per pixel).
Inscatter GetAerialPerspectiveAtVertex(sampler3D rayleigh_froxels, sampler3D mie_froxels,
                                       sampler3D transmittance_froxels, vec4 clip_position, float distance) {
  vec2 uv = clip_position.xy / clip_position.w * 0.5 + 0.5;
  return GetAerialPerspective(rayleigh_froxels, mie_froxels, transmittance_froxels, uv, distance);
}

// The segment's inscatter computed at the pixel instead of read from the froxels
// (kAerialPerPixel, frame.glsl): marched along the pixel's ray, or as two table reads.
Inscatter GetAerialPerspectivePerPixel(sampler2D transmittance_texture, sampler3D multiple_density_texture,
                                       sampler3D rayleigh_texture, sampler3D mie_texture,
                                       sampler3D multiple_texture, float r, float mu, float mu_s, float nu,
                                       float distance) {
  if (kAerialPerPixel == AERIAL_TABLE_DIFFERENCE) {
    return GetSkyInscatterToPointFromTables(transmittance_texture, rayleigh_texture, mie_texture,
                                            multiple_texture, r, mu, mu_s, nu, distance);
  }
  return GetSkyInscatterToPoint(transmittance_texture, multiple_density_texture, r, mu, mu_s, nu, distance);
}

// nu: the cosine between the view ray toward a camera-relative point and the sun.
float ViewSunCosine(vec3 relative_position) { return dot(normalize(relative_position), AERIAL_FRAME.sun_direction.xyz); }

// What the camera sees of a surface of radiance L through a segment of air:
// L T + I_R P_R(nu) + I_M P_M(g, nu) (Bruneton and Neyret 2008, eq. 16 and 17, with the
// inscatter read instead of computed).
vec3 ApplyAerialPerspective(vec3 surface_radiance, Inscatter segment, float nu) {
  return surface_radiance * segment.transmittance + ApplyPhaseFunctions(segment, nu);
}

// The sky along a unit view ray (camera-relative world) that meets no geometry, from the tables
// (aerial::Tables): the whole ray's inscatter with the phases of the ray itself, and
// behind it the sun's disc or the bare planet. aerial's sky pass draws this in the per-pixel modes;
// in froxel mode it reads the same from a per-frame sky-view table (sky_view.glsl).
vec3 GetSkyRadianceAlongRay(sampler2D transmittance_texture, sampler3D rayleigh_texture, sampler3D mie_texture,
                            sampler3D multiple_texture, sampler2D irradiance_texture, vec3 ray) {
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  // Bruneton 2017's demo reads the sky as the tables hold it, without the Earth's shadow corrected.
  Inscatter sky = kAerialPerPixel == AERIAL_TABLE_DIFFERENCE
                      ? GetSkyInscatterFromTables(transmittance_texture, rayleigh_texture, mie_texture,
                                                  multiple_texture, r, mu, mu_s, nu)
                      : GetSkyInscatter(transmittance_texture, rayleigh_texture, mie_texture, multiple_texture,
                                        r, mu, mu_s, nu);
  vec3 background = GetBackgroundThroughAtmosphere(transmittance_texture, irradiance_texture, ray, r, mu,
                                                   sky.transmittance);
  return ApplyPhaseFunctions(sky, nu) + ShadeBackground(background, RayIntersectsGround(r, mu), ray);
}

#endif
