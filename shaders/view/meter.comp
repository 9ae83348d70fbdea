#version 450
// The viewer's exposure meter: the log-average luminance of the frame's middle pixels
// (LogAverageLuminance, aerial/image/exposure.h) on the GPU, so that no frame is read back. It
// samples a 64x64 lattice of the frame's radiance into a histogram of log2 luminance (256 bins
// of 0.1875 stop over [-16, 32]: a moonless night to the sun's disc), then averages the bins'
// centers between the metered fractions of the samples. One workgroup of 256 invocations, 16
// samples each.
layout(local_size_x = 16, local_size_y = 16) in;
layout(set = 0, binding = 0) uniform sampler2D radiance_image;
layout(std430, set = 0, binding = 1) writeonly buffer Meter {
  float mean_log_luminance;  // natural logarithm, cd/m^2
} meter;
layout(push_constant) uniform Push {
  vec4 luminance_weights;  // xyz: cd/m^2 per unit of each channel (kLuminancePerChannel)
  vec4 limits;             // x: kMinLuminance, y, z: kMeteredLowFraction, kMeteredHighFraction
} push;

const int kLattice = 64;
const int kBins = 256;
const float kLog2Min = -16.0, kLog2Max = 32.0;
shared uint bins[kBins];

float BinCenter(int bin) { return kLog2Min + (float(bin) + 0.5) * (kLog2Max - kLog2Min) / float(kBins); }

void main() {
  bins[gl_LocalInvocationIndex] = 0u;
  barrier();
  ivec2 size = textureSize(radiance_image, 0);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      vec2 node = vec2(gl_LocalInvocationID.xy * 4u + uvec2(i, j)) + 0.5;
      ivec2 texel = min(ivec2(node / float(kLattice) * vec2(size)), size - 1);
      float luminance = dot(texelFetch(radiance_image, texel, 0).rgb, push.luminance_weights.xyz);
      // The negated test is also true for NaN.
      if (!(luminance > push.limits.x) || isinf(luminance)) luminance = push.limits.x;
      float unit = (log2(luminance) - kLog2Min) / (kLog2Max - kLog2Min);
      atomicAdd(bins[clamp(int(unit * float(kBins)), 0, kBins - 1)], 1u);
    }
  }
  barrier();
  if (gl_LocalInvocationIndex != 0u) return;
  float samples = float(kLattice * kLattice);
  float low = push.limits.y * samples, high = push.limits.z * samples;
  float rank = 0.0, sum = 0.0;
  for (int bin = 0; bin < kBins; ++bin) {
    float count = float(bins[bin]);
    float inside = max(min(rank + count, high) - max(rank, low), 0.0);
    sum += inside * BinCenter(bin);
    rank += count;
  }
  meter.mean_log_luminance = sum / (high - low) * log(2.0);
}
