#include "aerial/vk/pipeline_cache.h"

#include <gtest/gtest.h>

#include "aerial/error.h"
#include "aerial/vk/compute_pipeline.h"
#include "aerial/vk/context.h"
#include "aerial/vk/graphics_pipeline.h"

namespace aerial::vk {
namespace {

// A key holds each value with its size: values split differently give different keys.
TEST(PipelineKey, TellsApartValuesSplitDifferently) {
  EXPECT_NE(PipelineKey().Add("ab").Add("c").bytes(), PipelineKey().Add("a").Add("bc").bytes());
  EXPECT_NE(PipelineKey().Add(std::vector<int32_t>{1}).Add(std::vector<int32_t>{}).bytes(),
            PipelineKey().Add(std::vector<int32_t>{}).Add(std::vector<int32_t>{1}).bytes());
  EXPECT_EQ(PipelineKey().Add("shader").Add(uint64_t(3)).bytes(), PipelineKey().Add("shader").Add(uint64_t(3)).bytes());
}

const SlotLayout kToneMapSlots = {{"radiance_image", kSampled}, {"display_values", kStorageImage}};

// A pipeline asked for again with the same arguments is the one built before, also once the
// first pass that asked for it is gone; another specialization or other state is another
// pipeline; a build that fails (slots that do not match the shader) keeps nothing, so the next
// request fails the same way; a pipeline for a render pass is never shared.
TEST(PipelineCache, SharesWhatWasBuiltForTheSameArgumentsAndOnlyThat) {
  Context context({.validation = true});
  const int before = Context::ValidationMessageCount();
  {
    ComputePipeline first(context, "test/tone_map.comp", kToneMapSlots);
  }
  EXPECT_EQ(context.pipelines().size(), 1u);
  ComputePipeline again(context, "test/tone_map.comp", kToneMapSlots);
  EXPECT_EQ(context.pipelines().size(), 1u);
  ComputePipeline specialized(context, "test/tone_map.comp", kToneMapSlots, 0, {1});
  EXPECT_EQ(context.pipelines().size(), 2u);

  SlotLayout wrong = kToneMapSlots;
  wrong[0].type = kStorageImage;
  for (int i = 0; i < 2; ++i) EXPECT_THROW(ComputePipeline(context, "test/tone_map.comp", wrong), Error) << i;
  EXPECT_EQ(context.pipelines().size(), 2u);

  GraphicsPipelineCreateInfo triangle{.vertex_shader = "test/triangle.vert",
                                      .fragment_shader = "test/triangle.frag",
                                      .vertex_stride = 32,
                                      .attributes = {{kRgba32f, 0}, {kRgba32f, 16}},
                                      .color_formats = {kRgba32f}};
  GraphicsPipeline drawn(context, triangle);
  GraphicsPipeline drawn_again(context, triangle);
  EXPECT_EQ(context.pipelines().size(), 3u);
  triangle.alpha_blend = true;
  GraphicsPipeline blended(context, triangle);
  EXPECT_EQ(context.pipelines().size(), 4u);
  EXPECT_EQ(Context::ValidationMessageCount(), before);
}

}  // namespace
}  // namespace aerial::vk
