#version 450
#extension GL_GOOGLE_include_directive : require
// Sky-view pass: fills the per-frame sky-view table (sky_view.glsl) from the 4D or 3D tables, and
// adds the correction of the tables' read (GetSkyInscatterCorrection) interpolated from the
// lattice that sky_view_correction.comp wrote just before.
//
// The sky's pixels read two of its images (sky.frag): Rayleigh's inscatter with its phase function
// applied here, at the texel's own view-sun angle, plus below the horizon the ground seen through
// the air; and Mie's inscatter without phase, whose forward peak only a pixel's own angle resolves.
// Rayleigh's phase, 3/(16 pi) (1 + nu^2), is smooth: interpolated with the inscatter over a texel
// (about a degree) it is within 2e-4 of the pixel's own. The third image, the background (the
// transmittance above the horizon), is read only around the sun's disc (sun_disc.frag).
//
// The alpha of the first and third images holds the horizon's zenith angle at the camera the table
// was made for: a table kept while the camera climbs a little (frame_cache_policy.h) is then read
// with its own rows' directions (GetSkyViewUv), not with the rows of the camera's new horizon.
#include "blocks_not_inlined.glsl"
#include "sky_view.glsl"
#include "surface.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler2D irradiance_texture;
layout(set = 0, binding = 7) writeonly uniform image2D rayleigh_sky;
layout(set = 0, binding = 8) writeonly uniform image2D mie_sky;
layout(set = 0, binding = 9) writeonly uniform image2D background_sky;
layout(set = 0, binding = 10, rgba32f) readonly uniform image2D rayleigh_correction;
layout(set = 0, binding = 11, rgba32f) readonly uniform image2D mie_correction;
layout(push_constant) uniform Size { ivec2 size; } table;

// The correction at a texel from the four lattice nodes around it (GetSkyViewLatticeCell).
#define INTERPOLATE_LATTICE(lattice, node, t)                                                   \
  mix(mix(imageLoad(lattice, node).rgb, imageLoad(lattice, node + ivec2(1, 0)).rgb, t.x),       \
      mix(imageLoad(lattice, node + ivec2(0, 1)).rgb, imageLoad(lattice, node + ivec2(1, 1)).rgb, \
          t.x),                                                                                 \
      t.y)

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, table.size))) return;
  SkyViewRay ray = GetSkyViewRay(texel, table.size);
  Inscatter sky = GetSkyInscatterFromTables(transmittance_texture, rayleigh_texture, mie_texture,
                                            multiple_texture, ray.r, ray.mu, ray.mu_s, ray.nu);
  if (SkyInscatterCorrectionApplies(AERIAL_ATMOSPHERE.scattering_size)) {
    ivec2 node;
    vec2 t;
    GetSkyViewLatticeCell(texel, table.size, node, t);
    AddSkyInscatterCorrection(INTERPOLATE_LATTICE(rayleigh_correction, node, t),
                              INTERPOLATE_LATTICE(mie_correction, node, t), sky);
  }
  vec3 background = GetBackgroundThroughAtmosphere(transmittance_texture, irradiance_texture, ray.direction,
                                                   ray.r, ray.mu, sky.transmittance);
  vec3 ground = RayIntersectsGround(ray.r, ray.mu) ? background : vec3(0.0);
  float theta_h = HorizonZenithAngle(ray.r);
  imageStore(rayleigh_sky, texel, vec4(sky.rayleigh * RayleighPhaseFunction(ray.nu) + ground, theta_h));
  imageStore(mie_sky, texel, vec4(sky.mie, 0.0));
  imageStore(background_sky, texel, vec4(background, theta_h));
}
