// The table cache (~/.cache/aerial/*.tables). Its header and tables carry XXH64 checksums, so
// mutated bytes almost never get past the header checksum. The first input byte picks a mode:
// - even: the rest is the file as it is, for the prefix checks (magic, version, sizes, checksum);
// - odd: the rest is sealed into a cache with a valid prefix and header checksum, so mutations
//   reach the header's parser: bytes 1-2 give the header section's length (little-endian), the
//   section follows (its first 16 bytes are also the expected key), then the tables' bytes.
// The sealed layout mirrors WriteTableCache (table_cache.cpp); a format change updates both.
#include <algorithm>
#include <cstring>
#include <span>
#include <vector>

#include "aerial/core/checksum.h"
#include "aerial/error.h"
#include "aerial/precompute/table_cache.h"
#include "fuzz_input.h"

namespace {

void Put(std::vector<uint8_t>& out, uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(uint8_t(value >> (8 * i)));
}

uint64_t Little64(const uint8_t* bytes) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = v << 8 | bytes[i];
  return v;
}

std::vector<uint8_t> Seal(std::span<const uint8_t> input, aerial::TableCacheKey& key) {
  size_t section_bytes = input.size() < 2 ? 0 : input[0] | size_t{input[1]} << 8;
  input = input.subspan(std::min<size_t>(2, input.size()));
  section_bytes = std::min(section_bytes, input.size());
  auto section = input.first(section_bytes);
  auto payload = input.subspan(section_bytes);
  if (section.size() >= 16) key = {Little64(section.data()), Little64(section.data() + 8)};

  std::vector<uint8_t> file = {'A', 'E', 'R', 'I', 'A', 'L', 'T', '\0'};
  Put(file, aerial::kTableCacheVersion, 4);
  Put(file, section.size(), 4);
  Put(file, 24 + section.size() + 8 + payload.size(), 8);
  file.insert(file.end(), section.begin(), section.end());
  Put(file, aerial::Checksum(std::as_bytes(std::span(file))), 8);
  file.insert(file.end(), payload.begin(), payload.end());
  return file;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  aerial::TableCacheKey key;
  std::vector<uint8_t> file(data + 1, data + size);
  if (data[0] & 1) file = Seal(file, key);
  auto path = aerial::fuzz::WriteInputFile(file.data(), file.size(), ".tables");
  try {
    aerial::ReadTableCache(path, key);
  } catch (const aerial::Error&) {
  }
  return 0;
}
