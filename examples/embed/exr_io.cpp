// EXR files of the frame (exr_io.h), with OpenEXR's C++ API.
#include "exr_io.h"

#include <limits>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

namespace {

constexpr const char* kChannels[4] = {"R", "G", "B", "distance"};

// One FLOAT slice per channel into the interleaved buffer; a channel the file lacks is filled
// with `fill` on reading.
Imf::FrameBuffer InterleavedSlices(const float* rgbd, const Imath::Box2i& window, float fill = 0.0f) {
  const size_t x_stride = 4 * sizeof(float);
  const size_t y_stride = x_stride * size_t(window.max.x - window.min.x + 1);
  Imf::FrameBuffer frame_buffer;
  for (int c = 0; c < 4; ++c) {
    frame_buffer.insert(kChannels[c], Imf::Slice::Make(Imf::FLOAT, rgbd + c, window, x_stride, y_stride, 1, 1,
                                                       c == 3 ? fill : 0.0));
  }
  return frame_buffer;
}

}  // namespace

void WriteExr(const std::filesystem::path& path, const RgbdImage& image) {
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const char* name : kChannels) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(InterleavedSlices(image.rgbd.data(), header.dataWindow()));
  file.writePixels(image.height);
}

RgbdImage ReadExr(const std::filesystem::path& path) {
  Imf::InputFile file(path.c_str());
  Imath::Box2i window = file.header().dataWindow();
  RgbdImage image{.width = window.max.x - window.min.x + 1, .height = window.max.y - window.min.y + 1};
  image.rgbd.resize(size_t(image.width) * image.height * 4);
  file.setFrameBuffer(InterleavedSlices(image.rgbd.data(), window, std::numeric_limits<float>::infinity()));
  file.readPixels(window.min.y, window.max.y);
  return image;
}
