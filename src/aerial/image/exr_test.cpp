#include "aerial/image/exr.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "aerial/core/atomic_file.h"
#include "aerial/error.h"
#include "aerial/image/image_writer.h"
#include "aerial/image/scratch_dir_test_util.h"

namespace aerial {
namespace {

// 7x5 (not square, odd width) so a swapped stride or transposed row order would show. Values are
// log-spaced over 1e-6..1e4, the range from deep-twilight sky to the solar disk, plus exact 0,
// a negative and a denormal, which a half or lossy encoding would all change.
ImageRgbF WideRangeImage() {
  ImageRgbF image{7, 5, std::vector<float>(7 * 5 * 4)};
  const size_t n = image.rgba.size();
  for (size_t i = 0; i < n; ++i)
    image.rgba[i] = static_cast<float>(std::pow(10.0, -6.0 + 10.0 * i / (n - 1)));
  image.rgba[1] = 0.0f;
  image.rgba[6] = -2.5f;
  image.rgba[9] = 1e-40f;  // denormal
  return image;
}

class Exr : public ScratchDirTest {};

TEST_F(Exr, RoundTripIsBitIdentical) {
  const ImageRgbF image = WideRangeImage();
  WriteImage(dir_ / "sky.exr", image, {});
  const ImageRgbF back = ReadExr(dir_ / "sky.exr");
  ASSERT_EQ(back.width, image.width);
  ASSERT_EQ(back.height, image.height);
  ASSERT_EQ(back.rgba.size(), image.rgba.size());
  // Float channels with lossless ZIP: no tolerance, compare the bit patterns.
  for (size_t i = 0; i < image.rgba.size(); ++i)
    EXPECT_EQ(std::bit_cast<uint32_t>(back.rgba[i]), std::bit_cast<uint32_t>(image.rgba[i]))
        << "index " << i << ": " << back.rgba[i] << " vs " << image.rgba[i];
  EXPECT_EQ(Entries(), std::vector<std::string>{"sky.exr"});
}

TEST_F(Exr, ChannelsAreFullFloat) {
  WriteImage(dir_ / "sky.exr", WideRangeImage(), {});
  Imf::InputFile file((dir_ / "sky.exr").c_str());
  for (const char* name : {"R", "G", "B", "A"}) {
    const Imf::Channel* channel = file.header().channels().findChannel(name);
    ASSERT_NE(channel, nullptr) << name;
    EXPECT_EQ(channel->type, Imf::FLOAT) << name;
  }
}

// Readers learn the colour space from the header: Rec. 709 primaries with the D65 white point
// (x 0.3127, y 0.3290), and (1, 1, 1) at 683 * 106.857 cd/m^2 (spectral radiance units).
TEST_F(Exr, HeaderNamesTheColourSpaceAndLuminance) {
  WriteImage(dir_ / "sky.exr", WideRangeImage(), {});
  Imf::InputFile file((dir_ / "sky.exr").c_str());
  ASSERT_TRUE(Imf::hasChromaticities(file.header()));
  const Imf::Chromaticities& c = Imf::chromaticities(file.header());
  EXPECT_NEAR(c.white.x, 0.3127f, 1e-4f);
  EXPECT_NEAR(c.white.y, 0.3290f, 1e-4f);
  EXPECT_NEAR(c.red.x, 0.64f, 1e-4f);
  EXPECT_NEAR(c.green.y, 0.60f, 1e-4f);
  EXPECT_NEAR(c.blue.x, 0.15f, 1e-4f);
  ASSERT_TRUE(Imf::hasWhiteLuminance(file.header()));
  EXPECT_NEAR(Imf::whiteLuminance(file.header()), 683.0 * 106.857, 1.0);
}

TEST_F(Exr, PixelAccessorIsRowMajorTopFirst) {
  ImageRgbF image = WideRangeImage();
  image.pixel(6, 0)[0] = 42.0f;  // last pixel of the top row
  image.pixel(0, 4)[2] = 7.0f;   // first pixel of the bottom row
  WriteImage(dir_ / "sky.exr", image, {});
  const ImageRgbF back = ReadExr(dir_ / "sky.exr");
  EXPECT_EQ(back.pixel(6, 0)[0], 42.0f);
  EXPECT_EQ(back.pixel(0, 4)[2], 7.0f);
  EXPECT_EQ(back.rgba[(0 * 7 + 6) * 4 + 0], 42.0f);
  EXPECT_EQ(back.rgba[(4 * 7 + 0) * 4 + 2], 7.0f);
}

TEST_F(Exr, ReadingGarbageNamesThePath) {
  WriteFileAtomically(dir_ / "fake.exr", std::string_view("not an OpenEXR file"));
  try {
    ReadExr(dir_ / "fake.exr");
    FAIL() << "expected aerial::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find((dir_ / "fake.exr").string()), std::string::npos)
        << e.what();
  }
}

TEST_F(Exr, ReadingMissingFileNamesThePath) {
  try {
    ReadExr(dir_ / "missing.exr");
    FAIL() << "expected aerial::Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.value(), (dir_ / "missing.exr").string());
  }
}

}  // namespace
}  // namespace aerial
