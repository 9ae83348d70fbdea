#include "aerial/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "aerial/core/atomic_file.h"
#include "aerial/error.h"
#include "aerial/image/image_writer.h"
#include "aerial/image/scratch_dir_test_util.h"

// The decoder is only needed here; STATIC keeps its symbols out of every other object.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace aerial {
namespace {

// 6x4 with a different radiance in every channel of every pixel (0 to ~30) and varying alpha,
// so a row/column swap, channel swap or dropped alpha would all show.
ImageRgbF Gradient() {
  ImageRgbF image{6, 4, std::vector<float>(6 * 4 * 4)};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      float* p = image.pixel(x, y);
      p[0] = 0.05f * x;
      p[1] = 0.3f * y * y;
      p[2] = std::pow(2.0f, static_cast<float>(x + y)) / 8.0f - 0.125f;
      p[3] = 1.0f - 0.1f * y;
    }
  return image;
}

class Png : public ScratchDirTest {};

// PNG is lossless for 8-bit RGBA, so decoded bytes must equal the tone map exactly.
TEST_F(Png, DecodesToToneMappedPixels) {
  const ImageRgbF image = Gradient();
  const ToneMapOptions tone_map{.exposure = 1.5};
  WriteImage(dir_ / "sky.png", image, tone_map);
  const std::vector<std::byte> file = ReadFile(dir_ / "sky.png");

  int width = 0, height = 0, channels = 0;
  std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> decoded(
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(file.data()),
                            static_cast<int>(file.size()), &width, &height, &channels, 4),
      &stbi_image_free);
  ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
  EXPECT_EQ(width, 6);
  EXPECT_EQ(height, 4);
  EXPECT_EQ(channels, 4);
  const std::vector<uint8_t> expected = ToneMapToSrgb8(image, tone_map);
  EXPECT_EQ(std::vector<uint8_t>(decoded.get(), decoded.get() + expected.size()), expected);
  EXPECT_EQ(Entries(), std::vector<std::string>{"sky.png"});
}

TEST_F(Png, UpperCaseExtensionWritesPng) {
  WriteImage(dir_ / "SKY.PNG", Gradient(), {});
  const std::vector<std::byte> file = ReadFile(dir_ / "SKY.PNG");
  ASSERT_GE(file.size(), 8u);
  // PNG signature: \x89 P N G.
  EXPECT_EQ(file[1], std::byte{'P'});
  EXPECT_EQ(file[2], std::byte{'N'});
  EXPECT_EQ(file[3], std::byte{'G'});
}

TEST(PngEncode, RejectsBufferOfWrongLength) {
  EXPECT_THROW(EncodePng(std::vector<uint8_t>(10), 2, 2), Error);
}

}  // namespace
}  // namespace aerial
