#pragma once
// Checksum of table-cache files (precompute/table_cache.h). The tables are about 40 MB, so the
// hash must run near memory speed: XXH64 (Y. Collet, xxHash spec rev. 0.1.1) does ~10 GB/s on one
// core, detects every single-bit flip and almost all burst errors, and is a published,
// byte-exact algorithm, so a file can be verified by another tool (`xxhsum -H1`). The
// implementation is the reference one, Debian's libxxhash (xxhash.h).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace aerial {

// XXH64 of bytes with seed 0. Not cryptographic: it detects corruption, not tampering.
uint64_t Checksum(std::span<const std::byte> bytes);
uint64_t Checksum(std::string_view text);

}  // namespace aerial
