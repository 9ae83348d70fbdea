#include "aerial/image/image_writer.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <limits>
#include <string>

#include "aerial/error.h"
#include "aerial/image/scratch_dir_test_util.h"

namespace aerial {
namespace {
namespace fs = std::filesystem;

ImageRgbF Grey(int width, int height) {
  return ImageRgbF{width, height, std::vector<float>(size_t{4} * width * height, 0.5f)};
}

// Runs f, which must throw aerial::Error, and returns it.
Error Thrown(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "expected aerial::Error";
  return Error("", "", "");
}

bool Mentions(const Error& e, const fs::path& path) {
  return std::string(e.what()).find(path.string()) != std::string::npos;
}

class ImageWriter : public ScratchDirTest {};

TEST_F(ImageWriter, FormatFromExtensionIgnoresCase) {
  EXPECT_EQ(ImageFormatFromPath("a/b.exr", "out"), ImageFormat::kExr);
  EXPECT_EQ(ImageFormatFromPath("b.ExR", "out"), ImageFormat::kExr);
  EXPECT_EQ(ImageFormatFromPath("b.png", "out"), ImageFormat::kPng);
  EXPECT_EQ(ImageFormatFromPath("b.PNG", "out"), ImageFormat::kPng);
}

// The library names the path as itself; a caller's check names the path as the caller does.
TEST_F(ImageWriter, UnknownExtensionNamesTheFieldAndWritesNothing) {
  for (const fs::path& path : {dir_ / "sky.jpg", dir_ / "sky", dir_ / "exr"}) {
    const Error e = Thrown([&] { WriteImage(path, Grey(2, 2), {}); });
    EXPECT_EQ(e.field(), "image path");
    EXPECT_EQ(e.value(), path.string());
    EXPECT_EQ(Thrown([&] { CheckImageOutputPath(path, "--screenshot"); }).field(), "--screenshot");
    EXPECT_EQ(Thrown([&] { CheckImageOutputPath(path, "output.image"); }).field(), "output.image");
  }
  EXPECT_TRUE(Entries().empty());
}

// /proc refuses new entries even to root, so this fails on every machine.
TEST_F(ImageWriter, UnwritableDirectoryNamesPathAndLeavesNothing) {
  const fs::path path = "/proc/aerial-nope/x.exr";
  EXPECT_TRUE(Mentions(Thrown([&] { CheckImageOutputPath(path, "--out"); }), path));
  EXPECT_TRUE(Mentions(Thrown([&] { WriteImage(path, Grey(2, 2), {}); }), path));
  EXPECT_TRUE(Mentions(Thrown([&] { WriteImage("/proc/aerial-nope/x.png", Grey(2, 2), {}); }),
                       "/proc/aerial-nope/x.png"));
  EXPECT_FALSE(fs::exists("/proc/aerial-nope"));
}

TEST_F(ImageWriter, ParentIsRegularFileNamesPathAndLeavesNothing) {
  std::ofstream(dir_ / "file") << "not a directory";
  for (const char* name : {"x.exr", "x.png"}) {
    const fs::path path = dir_ / "file" / name;
    EXPECT_TRUE(Mentions(Thrown([&] { CheckImageOutputPath(path, "--out"); }), path));
    EXPECT_TRUE(Mentions(Thrown([&] { WriteImage(path, Grey(2, 2), {}); }), path));
  }
  EXPECT_EQ(Entries(), std::vector<std::string>{"file"});
}

TEST_F(ImageWriter, AbsurdSizeIsRejectedBeforeWriting) {
  for (const auto& [w, h] : {std::pair{0, 4}, {4, -1}, {16385, 1}, {1, 16385}}) {
    ImageRgbF image{w, h, {}};
    EXPECT_EQ(Thrown([&] { WriteImage(dir_ / "sky.exr", image, {}); }).field(), "image size");
    EXPECT_EQ(Thrown([&] { WriteImage(dir_ / "sky.png", image, {}); }).field(), "image size");
  }
  // Right sides but a buffer too short for them: reading it would run off the end.
  ImageRgbF short_buffer{4, 4, std::vector<float>(4 * 4 * 3)};
  EXPECT_EQ(Thrown([&] { WriteImage(dir_ / "sky.exr", short_buffer, {}); }).field(),
            "image size");
  EXPECT_TRUE(Entries().empty());
}

// A frame of NaN pixels (from a yaw of 5.8e307 degrees) must not be written with exit status 0.
TEST_F(ImageWriter, NonFiniteFrameIsRefusedNamingThePixel) {
  ImageRgbF image = Grey(3, 2);
  image.rgba[4 * 4 + 1] = std::numeric_limits<float>::quiet_NaN();  // pixel (1, 1), green
  for (const char* name : {"sky.exr", "sky.png"}) {
    Error e = Thrown([&] { WriteImage(dir_ / name, image, {}); });
    EXPECT_EQ(e.field(), "frame");
    EXPECT_EQ(e.value(), "NaN or infinity at pixel (1, 1)");
  }
  EXPECT_TRUE(Entries().empty());
}

TEST_F(ImageWriter, FailedWriteKeepsPreviousFile) {
  WriteImage(dir_ / "sky.exr", Grey(3, 2), {});
  EXPECT_THROW(WriteImage(dir_ / "sky.exr", ImageRgbF{0, 0, {}}, {}), Error);
  EXPECT_EQ(ReadExr(dir_ / "sky.exr").width, 3);
  EXPECT_EQ(Entries(), std::vector<std::string>{"sky.exr"});
}

// A mistyped output directory is an error naming the path, and nothing is created.
TEST_F(ImageWriter, MissingParentDirectoryIsAnErrorAndNothingIsCreated) {
  try {
    CheckImageOutputPath(dir_ / "new" / "sky.png", "--out");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("new"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(Entries().empty());
}

}  // namespace
}  // namespace aerial
