#include "aerial/precompute/table_cache.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <limits>

#include "aerial/core/atomic_file.h"
#include "aerial/core/input_limits.h"
#include "aerial/error.h"

namespace aerial {
namespace {
namespace fs = std::filesystem;

constexpr TableCacheKey kKey{0x0123456789abcdefull, 0xfedcba9876543210ull};

CachedTable FakeTable(std::string name, uint32_t w, uint32_t h, uint32_t d, TexelFormat format,
                      int seed) {
  CachedTable t{std::move(name), w, h, d, format, {}};
  t.texels.resize(size_t{w} * h * d * TexelBytes(format));
  // Bytes below 0x40 keep every float's and half float's exponent short of all ones: finite
  // texels, as a cache file must hold.
  for (size_t i = 0; i < t.texels.size(); ++i) t.texels[i] = std::byte((i * 31 + seed) & 0x3f);
  return t;
}

// Two small tables, one per format, so both texel sizes and the table boundary are exercised.
TableCache FakeCache() {
  TableCache cache;
  cache.key = kKey;
  cache.description = "test: 4x4x2 rgba32f + 4x4 rgba16f";
  cache.tables.push_back(FakeTable("scattering", 4, 4, 2, TexelFormat::kRgba32f, 1));
  cache.tables.push_back(FakeTable("irradiance", 4, 4, 1, TexelFormat::kRgba16f, 2));
  return cache;
}

class TableCacheFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("aerial_table_cache_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = dir_ / "tables.bin";
    WriteTableCache(path_, FakeCache());
    bytes_ = ReadFile(path_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A plain (non-atomic, no fsync) write keeps the many corrupted variants fast.
  void Overwrite(std::span<const std::byte> bytes) const {
    std::ofstream(path_, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
  }

  // Reads the cache and returns the Error's field ("" if it was accepted).
  std::string ReadErrorField(const TableCacheKey& key = kKey) const {
    try {
      ReadTableCache(path_, key);
      return "";
    } catch (const Error& e) {
      EXPECT_EQ(e.where(), path_.string()) << e.what();
      return e.field();
    }
  }

  // Offset of the payload: the header checksum sits 8 bytes before it (see table_cache.h).
  size_t PayloadOffset() const {
    uint32_t header_bytes = 0;
    for (int i = 3; i >= 0; --i)
      header_bytes = header_bytes << 8 | std::to_integer<uint32_t>(bytes_[12 + i]);
    return 24 + header_bytes + 8;
  }

  fs::path dir_, path_;
  std::vector<std::byte> bytes_;
};

TEST_F(TableCacheFile, RoundTripIsBitExact) {
  TableCache original = FakeCache();
  TableCache read = ReadTableCache(path_, kKey);
  EXPECT_EQ(read.key, original.key);
  EXPECT_EQ(read.description, original.description);
  ASSERT_EQ(read.tables.size(), original.tables.size());
  for (size_t i = 0; i < read.tables.size(); ++i) {
    EXPECT_EQ(read.tables[i].name, original.tables[i].name);
    EXPECT_EQ(read.tables[i].width, original.tables[i].width);
    EXPECT_EQ(read.tables[i].height, original.tables[i].height);
    EXPECT_EQ(read.tables[i].depth, original.tables[i].depth);
    EXPECT_EQ(read.tables[i].format, original.tables[i].format);
    EXPECT_EQ(read.tables[i].texels, original.tables[i].texels);
  }
  EXPECT_EQ(PayloadOffset() + 512 + 128, bytes_.size());  // 4*4*2*16 + 4*4*8 texel bytes.
}

TEST_F(TableCacheFile, EmptyCacheRoundTrips) {
  WriteTableCache(path_, TableCache{kKey, "", {}});
  EXPECT_TRUE(ReadTableCache(path_, kKey).tables.empty());
}

// Checksums only say the texels are as written: a file written with a NaN (or an infinity) in a
// table, checksums and all, is refused as a precompute with one is. Before, probe read it and
// printed null, with exit status 0.
TEST_F(TableCacheFile, ANonFiniteTexelIsRefusedThoughItsChecksumsHold) {
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    TableCache cache = FakeCache();
    std::memcpy(cache.tables[0].texels.data() + 5 * 16 + 4, &bad, 4);  // texel (1, 1, 0), green
    WriteTableCache(path_, cache);
    try {
      ReadTableCache(path_, kKey);
      ADD_FAILURE() << "read";
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), "cache table \"scattering\"");
      EXPECT_EQ(e.value(), "NaN or infinity in table \"scattering\" at texel (1, 1, 0)");
    }
  }
}

TEST_F(TableCacheFile, FlippedPayloadByteNamesTheTable) {
  for (size_t i = PayloadOffset(); i < bytes_.size(); ++i) {
    std::vector<std::byte> corrupt = bytes_;
    corrupt[i] ^= std::byte{0x01};
    Overwrite(corrupt);
    std::string table = i < PayloadOffset() + 512 ? "scattering" : "irradiance";
    ASSERT_EQ(ReadErrorField(), "cache table \"" + table + "\" checksum") << "byte " << i;
  }
}

// Whatever header byte flips (magic, version, sizes, key, names, extents, checksums), the file
// is rejected; which check fires depends on the byte.
TEST_F(TableCacheFile, FlippedHeaderByteIsDetected) {
  for (size_t i = 0; i < PayloadOffset(); ++i) {
    for (std::byte flip : {std::byte{0x01}, std::byte{0x80}}) {
      std::vector<std::byte> corrupt = bytes_;
      corrupt[i] ^= flip;
      Overwrite(corrupt);
      std::string field = ReadErrorField();
      ASSERT_EQ(field.rfind("cache ", 0), 0u)
          << "byte " << i << " accepted or odd field: " << field;
    }
  }
  // The common case, a flip inside the header section, is reported as such.
  std::vector<std::byte> corrupt = bytes_;
  corrupt[30] ^= std::byte{0x04};  // inside the atmosphere hash.
  Overwrite(corrupt);
  EXPECT_EQ(ReadErrorField(), "cache header checksum");
}

TEST_F(TableCacheFile, TruncatedFileIsDetected) {
  const size_t payload = PayloadOffset();
  for (size_t length : {size_t{0}, size_t{1}, size_t{7}, size_t{8}, size_t{23}, size_t{24},
                        payload - 8, payload, payload + 100, bytes_.size() - 1}) {
    Overwrite(std::span(bytes_).first(length));
    std::string field = ReadErrorField();
    EXPECT_EQ(field, "cache size") << "length " << length;
  }
}

TEST_F(TableCacheFile, TrailingBytesAreDetected) {
  std::vector<std::byte> longer = bytes_;
  longer.push_back(std::byte{0});
  Overwrite(longer);
  EXPECT_EQ(ReadErrorField(), "cache size");
}

TEST_F(TableCacheFile, OtherKeyIsStale) {
  EXPECT_EQ(ReadErrorField({kKey.atmosphere_hash + 1, kKey.options_hash}), "cache key");
  EXPECT_EQ(ReadErrorField({kKey.atmosphere_hash, kKey.options_hash ^ 1}), "cache key");
  try {
    ReadTableCache(path_, {1, 2});
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("another parameter set"), std::string::npos) << e.what();
  }
}

// A file above the cap is refused from its size, before anything is read or allocated; one at
// the cap is read, and refused for what its header says (sparse files: nothing is written).
TEST_F(TableCacheFile, OversizeFileIsRefusedBeforeReading) {
  auto message = [&] {
    try {
      ReadTableCache(path_, kKey);
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), "cache size");
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  fs::resize_file(path_, kMaxTableCacheBytes + 1);
  EXPECT_NE(message().find("at most 1073741824 bytes (no table set is larger)"), std::string::npos);
  fs::resize_file(path_, kMaxTableCacheBytes);
  EXPECT_NE(message().find("(trailing bytes)"), std::string::npos);
}

TEST_F(TableCacheFile, UnknownVersionIsDetected) {
  std::vector<std::byte> other = bytes_;
  other[8] = std::byte{2};  // version 2, little-endian.
  Overwrite(other);
  EXPECT_EQ(ReadErrorField(), "cache version");
}

TEST_F(TableCacheFile, OtherFileIsNotACache) {
  Overwrite(
      std::as_bytes(std::span(std::string_view("P6\n4 4\n255\n.............................."))));
  EXPECT_EQ(ReadErrorField(), "cache magic");
}

TEST_F(TableCacheFile, MissingFileNamesPath) {
  fs::remove(path_);
  try {
    ReadTableCache(path_, kKey);
    FAIL() << "expected aerial::Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "cache file");
    EXPECT_NE(std::string(e.what()).find(path_.string()), std::string::npos) << e.what();
  }
}

TEST_F(TableCacheFile, WriteRejectsInconsistentTable) {
  TableCache cache = FakeCache();
  cache.tables[0].texels.pop_back();
  EXPECT_THROW(WriteTableCache(path_, cache), Error);
  cache = FakeCache();
  cache.tables[1].format = static_cast<TexelFormat>(7);
  EXPECT_THROW(WriteTableCache(path_, cache), Error);
  cache = FakeCache();
  cache.tables[1].depth = 0;
  cache.tables[1].texels.clear();
  EXPECT_THROW(WriteTableCache(path_, cache), Error);
  EXPECT_EQ(ReadFile(path_), bytes_);  // the previous file is untouched.
}

}  // namespace
}  // namespace aerial
