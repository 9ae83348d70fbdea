#include "aerial/core/checksum.h"

#include <xxhash.h>

namespace aerial {

uint64_t Checksum(std::span<const std::byte> bytes) { return XXH64(bytes.data(), bytes.size(), 0); }

uint64_t Checksum(std::string_view text) {
  return Checksum(std::as_bytes(std::span(text.data(), text.size())));
}

}  // namespace aerial
