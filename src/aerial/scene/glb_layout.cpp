#include "aerial/scene/glb_layout.h"

#include <cstdint>
#include <cstring>

#include "aerial/error.h"

namespace aerial {
namespace {

constexpr size_t kHeaderBytes = 12, kChunkHeaderBytes = 8;

// Little-endian, like the machines this runs on.
uint32_t U32At(const std::vector<unsigned char>& bytes, size_t offset) {
  uint32_t value;
  std::memcpy(&value, bytes.data() + offset, 4);
  return value;
}

}  // namespace

std::string_view CheckedGlbJson(const std::vector<unsigned char>& bytes, const std::string& where) {
  size_t size = bytes.size();
  if (size < kHeaderBytes + kChunkHeaderBytes || std::memcmp(bytes.data(), "glTF", 4) != 0) {
    throw Error("GLB header", std::to_string(size) + " bytes",
                "\"glTF\", a version, a length and a JSON chunk (at least 20 bytes)", where);
  }
  if (U32At(bytes, 8) != size) {
    throw Error("GLB length", std::to_string(U32At(bytes, 8)),
                std::to_string(size) + " (the file's size)", where);
  }
  // Each chunk: its header, then its length in bytes, within what is left of the file.
  std::string_view json;
  size_t offset = kHeaderBytes;
  for (size_t chunk = 0; offset < size; ++chunk) {
    std::string field = "GLB chunk[" + std::to_string(chunk) + "] length";
    if (size - offset < kChunkHeaderBytes) {
      throw Error(field, "missing (" + std::to_string(size - offset) + " bytes left)",
                  "a chunk header of 8 bytes", where);
    }
    uint64_t length = U32At(bytes, offset);
    uint64_t room = size - offset - kChunkHeaderBytes;
    if (length > room) {
      throw Error(field, std::to_string(length),
                  "at most " + std::to_string(room) + " bytes (the rest of the file)", where);
    }
    if (chunk == 0)
      json = {reinterpret_cast<const char*>(bytes.data()) + offset + kChunkHeaderBytes, length};
    offset += kChunkHeaderBytes + length;
  }
  return json;
}

}  // namespace aerial
