// The raster half of the Vulkan layer: a triangle drawn with depth into float targets lands where
// it should, is depth-tested with reversed Z, and blends with premultiplied alpha.
#include <gtest/gtest.h>

#include <array>
#include <cstring>

#include "aerial/vk/graphics_pipeline.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

struct TestVertex {
  std::array<float, 4> position;  // clip space
  std::array<float, 4> color;
};

class GraphicsPipelineTest : public GpuTest {
 protected:
  static constexpr uint32_t kSize = 16;
  vk::Buffer MakeBuffer(std::span<const std::byte> bytes, ::vk::BufferUsageFlags usage) {
    vk::Buffer buffer(SharedContext(), {.size = bytes.size(), .usage = usage, .host_visible = true});
    buffer.Write(bytes);
    return buffer;
  }
  std::array<float, 4> Pixel(const vk::Image& image, uint32_t x, uint32_t y) {
    std::vector<std::byte> texels = ReadBack(image);
    std::array<float, 4> pixel;
    std::memcpy(pixel.data(), texels.data() + (y * kSize + x) * 16, 16);
    return pixel;
  }
};

TEST_F(GraphicsPipelineTest, DrawsDepthTestsAndBlends) {
  vk::Context& context = SharedContext();
  vk::Image color(context, {.extent = {kSize, kSize, 1},
                            .usage = ::vk::ImageUsageFlagBits::eColorAttachment |
                                     ::vk::ImageUsageFlagBits::eTransferSrc});
  vk::Image depth(context, {.extent = {kSize, kSize, 1}, .format = ::vk::Format::eD32Sfloat,
                            .usage = ::vk::ImageUsageFlagBits::eDepthStencilAttachment});
  // A near (z = 0.8) red triangle over the left half and a far (z = 0.2) green one covering all;
  // with reversed Z the near one must win where they overlap.
  std::vector<TestVertex> vertices = {
      {{-1, -1, 0.8f, 1}, {1, 0, 0, 1}}, {{0, -1, 0.8f, 1}, {1, 0, 0, 1}}, {{-1, 1, 0.8f, 1}, {1, 0, 0, 1}},
      {{-1, -3, 0.2f, 1}, {0, 1, 0, 1}}, {{3, 1, 0.2f, 1}, {0, 1, 0, 1}}, {{-1, 1, 0.2f, 1}, {0, 1, 0, 1}}};
  std::vector<uint32_t> indices = {0, 1, 2, 3, 4, 5};
  vk::Buffer vertex_buffer = MakeBuffer(std::as_bytes(std::span(vertices)), ::vk::BufferUsageFlagBits::eVertexBuffer);
  vk::Buffer index_buffer = MakeBuffer(std::as_bytes(std::span(indices)), ::vk::BufferUsageFlagBits::eIndexBuffer);
  vk::GraphicsPipelineCreateInfo info{
      .vertex_shader = "test/triangle.vert", .fragment_shader = "test/triangle.frag",
      .vertex_stride = sizeof(TestVertex),
      .attributes = {{::vk::Format::eR32G32B32A32Sfloat, 0}, {::vk::Format::eR32G32B32A32Sfloat, 16}},
      .color_formats = {::vk::Format::eR32G32B32A32Sfloat},
      .depth_format = ::vk::Format::eD32Sfloat};
  vk::GraphicsPipeline opaque(context, info);
  info.alpha_blend = true;
  info.depth_write = false;
  vk::GraphicsPipeline blended(context, info);

  std::vector<TestVertex> glass = {{{-1, -3, 0.9f, 1}, {0, 0, 1, 0.5f}}, {{3, 1, 0.9f, 1}, {0, 0, 1, 0.5f}},
                                   {{-1, 1, 0.9f, 1}, {0, 0, 1, 0.5f}}};
  vk::Buffer glass_buffer = MakeBuffer(std::as_bytes(std::span(glass)), ::vk::BufferUsageFlagBits::eVertexBuffer);
  context.Submit([&](const auto& cmd) {
    color.InitializeLayout(cmd);
    depth.InitializeLayout(cmd);
    {
      vk::Rendering rendering(cmd, {.colors = {&color}, .clear_colors = {std::array<float, 4>{0, 0, 0, 0}},
                                    .depth = &depth, .clear_depth = 0.0f});
      opaque.Bind(cmd, {});
      vk::BindMesh(cmd, vertex_buffer, index_buffer);
      vk::DrawIndexed(cmd, 6);
    }
    vk::FullBarrier(cmd);
  });
  auto left = Pixel(color, 2, 8);
  auto right = Pixel(color, 13, 8);
  EXPECT_EQ(left[0], 1.0f) << "the near red triangle wins the depth test";
  EXPECT_EQ(left[1], 0.0f);
  EXPECT_EQ(right[1], 1.0f) << "the far green triangle covers the rest";

  context.Submit([&](const auto& cmd) {
    {
      vk::Rendering rendering(cmd, {.colors = {&color}, .clear_colors = {std::nullopt}, .depth = &depth});
      blended.Bind(cmd, {});
      vk::BindMesh(cmd, glass_buffer, index_buffer);
      vk::DrawIndexed(cmd, 3);
    }
    vk::FullBarrier(cmd);
  });
  auto glazed = Pixel(color, 13, 8);
  // Premultiplied blend: 0.5 * blue + (1 - 0.5) * green.
  EXPECT_FLOAT_EQ(glazed[1], 0.5f);
  EXPECT_FLOAT_EQ(glazed[2], 0.5f);
}

}  // namespace
}  // namespace aerial::testing
