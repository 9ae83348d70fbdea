#version 450
// The viewer's exposure meter: ReadMeter (aerial/image/exposure.h) on the GPU, so that no frame is
// read back. It samples a 64x64 lattice of the frame's radiance into two histograms of log2
// values (256 bins of 0.1875 stop over [-16, 32]: a moonless night to the sun's disc): the
// luminance, whose bins' centers are averaged between the metered fractions of the samples, and
// the brightest channel after the white balance, whose highlight fraction's bin is the highlight.
// One workgroup of 256 invocations, 16 samples each.
layout(local_size_x = 16, local_size_y = 16) in;
layout(set = 0, binding = 0) uniform sampler2D radiance_image;
layout(std430, set = 0, binding = 1) writeonly buffer Meter {
  float mean_log_luminance;  // natural logarithm, cd/m^2
  float log_highlight;       // natural logarithm, the same units
} meter;
layout(push_constant) uniform Push {
  vec4 luminance_weights;  // xyz: cd/m^2 per unit of each channel (kLuminancePerChannel)
  vec4 limits;             // x: kMinLuminance, y, z: kMeteredLowFraction, kMeteredHighFraction, w: kHighlightFraction
  vec4 highlight_weights;  // xyz: the white balance's gains times kRadiancePerNmToLuminance
} push;

const int kLattice = 64;
const int kBins = 256;
const float kLog2Min = -16.0, kLog2Max = 32.0;
shared uint luminance_bins[kBins];
shared uint highlight_bins[kBins];

float BinCenter(int bin) { return kLog2Min + (float(bin) + 0.5) * (kLog2Max - kLog2Min) / float(kBins); }

int Bin(float value) {
  // The negated test is also true for NaN.
  if (!(value > push.limits.x) || isinf(value)) value = push.limits.x;
  float unit = (log2(value) - kLog2Min) / (kLog2Max - kLog2Min);
  return clamp(int(unit * float(kBins)), 0, kBins - 1);
}

void main() {
  luminance_bins[gl_LocalInvocationIndex] = 0u;
  highlight_bins[gl_LocalInvocationIndex] = 0u;
  barrier();
  ivec2 size = textureSize(radiance_image, 0);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      vec2 node = vec2(gl_LocalInvocationID.xy * 4u + uvec2(i, j)) + 0.5;
      ivec2 texel = min(ivec2(node / float(kLattice) * vec2(size)), size - 1);
      vec3 radiance = texelFetch(radiance_image, texel, 0).rgb;
      vec3 balanced = radiance * push.highlight_weights.xyz;
      atomicAdd(luminance_bins[Bin(dot(radiance, push.luminance_weights.xyz))], 1u);
      atomicAdd(highlight_bins[Bin(max(balanced.r, max(balanced.g, balanced.b)))], 1u);
    }
  }
  barrier();
  if (gl_LocalInvocationIndex != 0u) return;
  float samples = float(kLattice * kLattice);
  float low = push.limits.y * samples, high = push.limits.z * samples;
  float rank = 0.0, sum = 0.0;
  for (int bin = 0; bin < kBins; ++bin) {
    float count = float(luminance_bins[bin]);
    float inside = max(min(rank + count, high) - max(rank, low), 0.0);
    sum += inside * BinCenter(bin);
    rank += count;
  }
  meter.mean_log_luminance = sum / (high - low) * log(2.0);
  // The bin holding the sample of rank floor(fraction x samples), as ReadMeter's nth_element.
  float highlight_rank = floor(push.limits.w * samples);
  rank = 0.0;
  int highlight_bin = kBins - 1;
  for (int bin = 0; bin < kBins; ++bin) {
    rank += float(highlight_bins[bin]);
    if (rank > highlight_rank) {
      highlight_bin = bin;
      break;
    }
  }
  meter.log_highlight = BinCenter(highlight_bin) * log(2.0);
}
