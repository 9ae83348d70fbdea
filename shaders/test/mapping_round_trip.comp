#version 450
#extension GL_GOOGLE_include_directive : require
// Test shader: every texel center of each table, mapped to physical parameters and back, must land
// on itself. Writes the largest error in texel units per table (as float bits: for non-negative
// floats the unsigned integer order is the float order, so atomicMax works).
#include "mappings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, set = 0, binding = 1) buffer Errors { uint max_error_bits[5]; };
// 0 transmittance, 1 irradiance, 2 scattering (ray-length mu axis), 3 scattering density (view
// zenith mu axis, in slot 4).
layout(push_constant) uniform Table { int table; } test;

void Record(int slot, float error_in_texels) {
  atomicMax(max_error_bits[slot], floatBitsToUint(abs(error_in_texels)));
}

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (test.table == 0) {
    ivec2 size = AERIAL_ATMOSPHERE.transmittance_size.xy;
    if (any(greaterThanEqual(texel.xy, size)) || texel.z > 0) return;
    vec2 uv = (vec2(texel.xy) + 0.5) / vec2(size);
    float r, mu;
    GetRMuFromTransmittanceTextureUv(uv, r, mu);
    vec2 error = (GetTransmittanceTextureUvFromRMu(r, mu) - uv) * vec2(size);
    Record(0, max(abs(error.x), abs(error.y)));
  } else if (test.table == 1) {
    ivec2 size = AERIAL_ATMOSPHERE.irradiance_size.xy;
    if (any(greaterThanEqual(texel.xy, size)) || texel.z > 0) return;
    vec2 uv = (vec2(texel.xy) + 0.5) / vec2(size);
    float r, mu_s;
    GetRMuSFromIrradianceTextureUv(uv, r, mu_s);
    vec2 error = (GetIrradianceTextureUvFromRMuS(r, mu_s) - uv) * vec2(size);
    Record(1, max(abs(error.x), abs(error.y)));
  } else {
    ivec4 size = AERIAL_ATMOSPHERE.scattering_size;
    if (!IsScatteringTexel(size, texel)) return;
    int mu_axis = test.table == 2 ? MU_AXIS_RAY_LENGTH : MU_AXIS_VIEW_ZENITH;
    float r, mu, mu_s, nu;
    bool ground;
    GetRMuMuSNuFromScatteringTexel(size, mu_axis, texel, r, mu, mu_s, nu, ground);
    // The first r slice is the ground itself (r = R), where every downward ray has length 0: on
    // the ray-length axis the whole ground half maps to mu = -1 and cannot round-trip. Those
    // texels hold zero scattering by construction.
    if (mu_axis == MU_AXIS_RAY_LENGTH && texel.z == 0 && ground) return;
    // On the radiance tables nu is clamped to what (mu, mu_s) allow, so only the r, mu and mu_s
    // axes must round-trip there. The density tables' azimuth axis must too, except where the
    // sun or the view is at the zenith or nadir and every azimuth is the same direction.
    vec4 uvwz = GetScatteringTextureUvwzFromRMuMuSNu(size, mu_axis, r, mu, mu_s, nu, ground);
    int mu_s_index = texel.x % size.z;
    float error_mu_s = (uvwz.y - (float(mu_s_index) + 0.5) / float(size.z)) * float(size.z);
    float error_mu = (uvwz.z - (float(texel.y) + 0.5) / float(size.y)) * float(size.y);
    float error_r = (uvwz.w - (float(texel.z) + 0.5) / float(size.x)) * float(size.x);
    float error_azimuth = 0.0;
    if (mu_axis == MU_AXIS_VIEW_ZENITH && size.w > 1 &&
        (1.0 - mu * mu) * (1.0 - mu_s * mu_s) > 1e-6) {
      float last_slice = float(size.w - 1);
      error_azimuth = (uvwz.x - float(texel.x / size.z) / last_slice) * last_slice;
    }
    int slot = mu_axis == MU_AXIS_RAY_LENGTH ? 2 : 4;
    Record(slot, max(max(max(abs(error_mu_s), abs(error_mu)), abs(error_r)), abs(error_azimuth)));
    // Away from the two outermost texels, which both stand for the tangent ray itself (mu exactly
    // at the horizon, where "hits the ground" is a matter of rounding), a texel's half must agree
    // with the ray it stands for.
    bool horizon_texel = texel.y == 0 || texel.y == size.y - 1;
    bool ground_again = RayIntersectsGround(r, mu);
    Record(3, horizon_texel || ground_again == ground ? 0.0 : 1.0);
  }
}
