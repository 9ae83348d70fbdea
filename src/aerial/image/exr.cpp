#include "aerial/image/exr.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfEnvmapAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <exception>

#include "aerial/error.h"
#include "aerial/image/exposure.h"

namespace aerial {
namespace {

constexpr const char* kChannels[4] = {"R", "G", "B", "A"};

// One FLOAT slice per channel into the interleaved rgba buffer. Slice::Make offsets the base
// pointer by the data window origin itself, which avoids forming an out-of-range pointer.
Imf::FrameBuffer InterleavedFrameBuffer(float* rgba, const Imath::Box2i& window) {
  const size_t x_stride = 4 * sizeof(float);
  const size_t y_stride = x_stride * static_cast<size_t>(window.max.x - window.min.x + 1);
  Imf::FrameBuffer frame_buffer;
  for (int c = 0; c < 4; ++c) {
    // Fill values apply to channels the file lacks; only A may be missing (see DecodeExr).
    frame_buffer.insert(kChannels[c], Imf::Slice::Make(Imf::FLOAT, rgba + c, window, x_stride,
                                                       y_stride, 1, 1, /*fillValue=*/1.0));
  }
  return frame_buffer;
}

}  // namespace

std::vector<std::byte> EncodeExr(const ImageRgbF& image, const ExrHeaderExtras& extras) {
  CheckImageSize(image);
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.zipCompressionLevel() = 1;
  header.lineOrder() = Imf::INCREASING_Y;  // top row first, as in ImageRgbF
  for (const char* name : kChannels) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  // The colour space: linear sRGB (Rec. 709 primaries, D65 white, OpenEXR's default
  // chromaticities, written out so that readers need not assume them), and the luminance of
  // (1, 1, 1) in cd/m^2: channel values are spectral radiance units, W m^-2 sr^-1 nm^-1, whose
  // luminance is 683 lm/W times the integral of y-bar (spectrum/colour.h).
  Imf::addChromaticities(header, Imf::Chromaticities());
  Imf::addWhiteLuminance(header, float(kRadiancePerNmToLuminance));
  if (extras.envmap != ExrHeaderExtras::Envmap::kNone)
    Imf::addEnvmap(header, extras.envmap == ExrHeaderExtras::Envmap::kCube ? Imf::ENVMAP_CUBE : Imf::ENVMAP_LATLONG);
  for (const auto& [name, value] : extras.attributes) {
    if (const auto* text = std::get_if<std::string>(&value)) {
      header.insert(name, Imf::StringAttribute(*text));
    } else if (const auto* number = std::get_if<float>(&value)) {
      header.insert(name, Imf::FloatAttribute(*number));
    } else {
      const auto& v = std::get<std::array<float, 3>>(value);
      header.insert(name, Imf::V3fAttribute(Imath::V3f(v[0], v[1], v[2])));
    }
  }

  Imf::StdOSStream stream;
  {
    // The OutputFile destructor writes the line offset table, so it must end before str().
    Imf::OutputFile file(stream, header);
    // OpenEXR only reads the slices; the const_cast is its API's, not a write.
    file.setFrameBuffer(
        InterleavedFrameBuffer(const_cast<float*>(image.rgba.data()), header.dataWindow()));
    file.writePixels(image.height);
  }
  const std::string encoded = stream.str();
  const auto* first = reinterpret_cast<const std::byte*>(encoded.data());
  return std::vector<std::byte>(first, first + encoded.size());
}

ImageRgbF DecodeExr(std::span<const std::byte> bytes, const std::string& where) {
  try {
    Imf::StdISStream stream;
    stream.str(std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    Imf::InputFile file(stream);
    // A file without colour (e.g. luminance-only "Y") would otherwise read as silent black.
    for (const char* name : {"R", "G", "B"}) {
      if (file.header().channels().findChannel(name) == nullptr)
        throw Error("EXR channel", name, "R, G and B channels present", where);
    }
    const Imath::Box2i window = file.header().dataWindow();
    ImageRgbF image;
    image.width = window.max.x - window.min.x + 1;
    image.height = window.max.y - window.min.y + 1;
    // Check the size before allocating: a corrupt header could ask for any amount.
    CheckImageSize(image.width, image.height, where);
    image.rgba.resize(size_t{4} * static_cast<size_t>(image.width) * image.height);
    file.setFrameBuffer(InterleavedFrameBuffer(image.rgba.data(), window));
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error("file", where, std::string("a readable OpenEXR image (") + e.what() + ")");
  }
}

}  // namespace aerial
