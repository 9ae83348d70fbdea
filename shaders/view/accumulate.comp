#version 450
// One frame of a still view's antialiasing (viewer/frame_accumulator.h): the running mean of the
// jittered frames drawn so far, average += (frame - average) * weight with weight 1 / (frames so
// far), which makes it their plain mean whatever the order.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D radiance_image;
layout(set = 0, binding = 1, rgba32f) uniform image2D average_image;
layout(push_constant) uniform Push {
  float weight;  // 1 for the first frame: the old contents are not read
} push;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(average_image)))) return;
  vec4 frame = texelFetch(radiance_image, texel, 0);
  vec4 average = push.weight < 1.0 ? imageLoad(average_image, texel) : frame;
  imageStore(average_image, texel, mix(average, frame, push.weight));
}
