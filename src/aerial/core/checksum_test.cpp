#include "aerial/core/checksum.h"

#include <gtest/gtest.h>

#include <chrono>
#include <vector>

namespace aerial {
namespace {

// Published XXH64 vectors (seed 0). The lengths cover every code path: empty, single bytes only,
// 4-byte + byte tail, 8-byte tail, and 39 bytes for the 32-byte stripe loop.
TEST(Checksum, MatchesPublishedXxh64Vectors) {
  EXPECT_EQ(Checksum(std::string_view("")), 0xEF46DB3751D8E999ull);
  EXPECT_EQ(Checksum(std::string_view("a")), 0xD24EC4F1A98C6E5Bull);
  EXPECT_EQ(Checksum(std::string_view("abc")), 0x44BC2CF5AD770999ull);
  EXPECT_EQ(Checksum(std::string_view("Hello, World!")), 0xC49AACF8080FE47Full);
  EXPECT_EQ(Checksum(std::string_view("Nobody inspects the spammish repetition")),
            0xFBCEA83C8A378BF1ull);
}

TEST(Checksum, DetectsEverySingleBitFlip) {
  std::vector<std::byte> bytes(100);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = std::byte(i * 37);
  const uint64_t reference = Checksum(bytes);
  for (size_t i = 0; i < bytes.size(); ++i) {
    for (int bit = 0; bit < 8; ++bit) {
      bytes[i] ^= std::byte(1 << bit);
      EXPECT_NE(Checksum(bytes), reference) << "byte " << i << " bit " << bit;
      bytes[i] ^= std::byte(1 << bit);
    }
  }
}

TEST(Checksum, HashesTableSizedInputQuickly) {
  // 40 MB is a full set of float32 tables. Even an unoptimized (-O0) build hashes well above
  // 200 MB/s, so 1 s only fails if the hash is pathologically slow.
  std::vector<std::byte> bytes(40u << 20, std::byte{1});
  auto start = std::chrono::steady_clock::now();
  volatile uint64_t sink = Checksum(bytes);
  (void)sink;
  std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  EXPECT_LT(elapsed.count(), 1.0);
}

}  // namespace
}  // namespace aerial
