#version 450
#extension GL_GOOGLE_include_directive : require
// Sky-view pass: fills the per-frame sky-view table (sky_view.glsl) from the 4D or 3D tables.
//
// The single scattering correction of the low sun (GetSingleScatteringCorrection, sky_lookup.glsl)
// marches five suns along each ray: at every texel it cost 80 ms per rebuild at sunset on
// lavapipe. It changes slowly over the table, so each workgroup of 16x6 texels computes it at a
// lattice of 5x3 nodes, every 4 texels in azimuth and 3 in zenith, and its texels interpolate
// them bilinearly (15 of 96 invocations march: on lavapipe's 8-wide vectors, 2 of 12).
// A workgroup never straddles the horizon row (the table's halves are 54 rows, 9 groups of 6),
// where the correction jumps with the ray's end (ground or space); a half's last node is its
// last row. Neighbouring groups share their border nodes, so the correction is continuous.
#include "sky_view.glsl"
#include "surface.glsl"
layout(local_size_x = 16, local_size_y = 6) in;
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 3) uniform sampler3D rayleigh_texture;
layout(set = 0, binding = 4) uniform sampler3D mie_texture;
layout(set = 0, binding = 5) uniform sampler3D multiple_texture;
layout(set = 0, binding = 6) uniform sampler2D irradiance_texture;
layout(set = 0, binding = 7) writeonly uniform image2D rayleigh_sky;
layout(set = 0, binding = 8) writeonly uniform image2D mie_sky;
layout(set = 0, binding = 9) writeonly uniform image2D background_sky;
layout(push_constant) uniform Size { ivec2 size; } table;

const ivec2 NODE_SPACING = ivec2(4, 3);
const ivec2 NODE_COUNT = ivec2(5, 3);  // gl_WorkGroupSize.xy / NODE_SPACING + 1
shared vec3 node_rayleigh[NODE_COUNT.y][NODE_COUNT.x];
shared vec3 node_mie[NODE_COUNT.y][NODE_COUNT.x];

struct SkyViewRay {
  vec3 direction;
  float r, mu, mu_s, nu;
};

SkyViewRay GetSkyViewRay(ivec2 texel) {
  SkyViewRay ray;
  ray.r = length(frame.camera_planet_position.xyz);
  vec2 angles = GetSkyViewDirection(ray.r, (vec2(texel) + 0.5) / vec2(table.size), table.size);
  vec3 up, toward_sun, side;
  GetSkyViewFrame(up, toward_sun, side);
  float sin_theta = sin(angles.y);
  ray.direction = up * cos(angles.y) +
                  sin_theta * (toward_sun * angles.x + side * sqrt(max(1.0 - angles.x * angles.x, 0.0)));
  ray.mu = dot(up, ray.direction);
  ray.mu_s = dot(up, frame.sun_direction.xyz);
  ray.nu = dot(ray.direction, frame.sun_direction.xyz);
  return ray;
}

// The texel of the workgroup's node (i, j): every NODE_SPACING from the group's first texel, at
// most the last texel of the table (azimuth) or of the group's half (zenith).
ivec2 GetNodeTexel(ivec2 node) {
  ivec2 first = ivec2(gl_WorkGroupID.xy * gl_WorkGroupSize.xy);
  int half_rows = table.size.y / 2;
  ivec2 last = ivec2(table.size.x - 1, first.y < half_rows ? half_rows - 1 : table.size.y - 1);
  return min(first + node * NODE_SPACING, last);
}

void main() {
  if (gl_LocalInvocationIndex < NODE_COUNT.x * NODE_COUNT.y) {
    ivec2 node = ivec2(gl_LocalInvocationIndex % NODE_COUNT.x, gl_LocalInvocationIndex / NODE_COUNT.x);
    SkyViewRay ray = GetSkyViewRay(GetNodeTexel(node));
    GetSingleScatteringCorrection(transmittance_texture, atmosphere.scattering_size, ray.r, ray.mu,
                                  ray.mu_s, ray.nu, node_rayleigh[node.y][node.x],
                                  node_mie[node.y][node.x]);
  }
  barrier();
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, table.size))) return;
  SkyViewRay ray = GetSkyViewRay(texel);
  Inscatter sky = GetSkyInscatterFromTables(transmittance_texture, rayleigh_texture, mie_texture,
                                            multiple_texture, ray.r, ray.mu, ray.mu_s, ray.nu);
  // The lattice cell around the texel, and its place in it.
  ivec2 cell = ivec2(gl_LocalInvocationID.xy) / NODE_SPACING;
  ivec2 low = GetNodeTexel(cell), high = GetNodeTexel(cell + 1);
  vec2 t = vec2(texel - low) / vec2(max(high - low, ivec2(1)));
  vec3 rayleigh = mix(mix(node_rayleigh[cell.y][cell.x], node_rayleigh[cell.y][cell.x + 1], t.x),
                      mix(node_rayleigh[cell.y + 1][cell.x], node_rayleigh[cell.y + 1][cell.x + 1], t.x), t.y);
  vec3 mie = mix(mix(node_mie[cell.y][cell.x], node_mie[cell.y][cell.x + 1], t.x),
                 mix(node_mie[cell.y + 1][cell.x], node_mie[cell.y + 1][cell.x + 1], t.x), t.y);
  AddSingleScatteringCorrection(rayleigh, mie, sky);
  imageStore(rayleigh_sky, texel, vec4(sky.rayleigh, 0.0));
  imageStore(mie_sky, texel, vec4(sky.mie, 0.0));
  vec3 background = GetBackgroundThroughAtmosphere(transmittance_texture, irradiance_texture, ray.direction,
                                                   ray.r, ray.mu, sky.transmittance);
  imageStore(background_sky, texel, vec4(background, 1.0));
}
