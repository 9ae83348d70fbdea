#pragma once
// Antialiasing of a still view by accumulation. Once the view stops, the viewer draws it again
// with the camera jittered (Camera::jitter_px) to the centres of each pixel's four quadrants, one
// frame at a time, and averages the frames here (shaders/view/accumulate.comp). The mean of the
// four is `aerial render`'s default 2x2 supersampled frame: a moving view pays nothing for it, and
// a still one is antialiased after four frames (the progressive refinement of offline renderers'
// viewports; engines' temporal antialiasing reprojects instead, to keep it while moving).
#include <array>
#include <optional>

#include <glm/glm.hpp>

#include "aerial/image.h"
#include "aerial/renderer.h"
#include "aerial/vk/compute_pipeline.h"
#include "aerial/vk/resources.h"

namespace aerial::viewer {

// The jitters in the order they are drawn: opposite quadrants first, so that two frames already
// sample both diagonals.
inline constexpr std::array<glm::dvec2, 4> kAccumulationJitters = {
    glm::dvec2{-0.25, -0.25}, glm::dvec2{0.25, 0.25}, glm::dvec2{0.25, -0.25}, glm::dvec2{-0.25, 0.25}};

// What accumulating the next frame does: the jitter to draw it with and its weight in the mean.
struct AccumulationStep {
  glm::dvec2 jitter_px;
  float weight;  // 1 / (frames averaged once it is added)
};
AccumulationStep NextAccumulationStep(int frames_averaged);

class FrameAccumulator {
 public:
  explicit FrameAccumulator(const vk::Context& context);

  int frames() const { return frames_; }
  bool complete() const { return frames_ == int(kAccumulationJitters.size()); }
  // The jitter of the next frame to add (not complete()).
  glm::dvec2 next_jitter() const { return NextAccumulationStep(frames_).jitter_px; }
  // Starts again: the view changed.
  void Reset() { frames_ = 0; }
  // Makes the mean the size of `extent`, dropping what it held. No frame in flight may still read
  // it (the caller waits for them).
  void Resize(VkExtent3D extent);
  bool Fits(VkExtent3D extent) const;

  // Adds `frame`, drawn with next_jitter(), to the mean (outside any render pass).
  void Record(const vk::CommandBuffer& cmd, const SampledImage& frame);
  // The mean of the frames added (frames() > 0), for the display pass.
  SampledImage mean() const;
  // The mean read back (frames() > 0, after its frames finished).
  ImageRgbF Read() const;

 private:
  const vk::Context& context_;
  vk::ComputePipeline pipeline_;
  ::vk::raii::Sampler nearest_;
  std::optional<vk::Image> mean_;
  int frames_ = 0;
};

}  // namespace aerial::viewer
