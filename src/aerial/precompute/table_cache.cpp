#include "aerial/precompute/table_cache.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <span>

#include "aerial/core/atomic_file.h"
#include "aerial/core/checksum.h"
#include "aerial/core/file_kind.h"
#include "aerial/core/input_limits.h"
#include "aerial/error.h"
#include "aerial/precompute/finite_tables.h"

namespace aerial {
namespace {

// Texels are stored as the host lays them out; GPUs and the CPU both read little-endian floats.
static_assert(std::endian::native == std::endian::little,
              "table caches store little-endian texels");

constexpr char kMagic[8] = {'A', 'E', 'R', 'I', 'A', 'L', 'T', '\0'};
constexpr uint64_t kPrefixBytes = 24;  // magic, version, header_bytes, file_bytes.
constexpr uint64_t kChecksumBytes = 8;

std::string Hex(uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(value));
  return text;
}

std::string Describe(const TableCacheKey& key) {
  return "atmosphere " + Hex(key.atmosphere_hash) + ", options " + Hex(key.options_hash);
}

// width * height * depth * texel size, or 0 when the format is unknown or the product
// overflows (a corrupt header must not make us allocate a wrapped-around size).
uint64_t ExpectedTexelBytes(const CachedTable& t) {
  uint64_t bytes = uint64_t{t.width} * t.height;  // < 2^64: both factors are below 2^32.
  if (t.depth != 0 && bytes > UINT64_MAX / t.depth) return 0;
  bytes *= t.depth;
  uint32_t texel = TexelBytes(t.format);
  if (texel == 0 || bytes > UINT64_MAX / texel) return 0;
  return bytes * texel;
}

// A table whose extent, format and byte count disagree (a bug when writing, corruption when
// reading).
[[noreturn]] void ThrowBadShape(const CachedTable& t, uint64_t bytes, const std::string& where) {
  throw Error("cache table \"" + t.name + "\"",
              std::to_string(t.width) + "x" + std::to_string(t.height) + "x" +
                  std::to_string(t.depth) + " texels, format " +
                  std::to_string(static_cast<uint32_t>(t.format)) + ", " + std::to_string(bytes) +
                  " bytes",
              "extents >= 1, format 0 (rgba32f, 16 bytes) or 1 (rgba16f, 8 bytes), and "
              "width * height * depth * texel size bytes",
              where);
}

// The tables listed in the header must exactly fill the rest of the file. (A wrapped-around
// sum in the message only happens for sizes that already failed.)
[[noreturn]] void ThrowPayloadMismatch(uint64_t listed, uint64_t available,
                                       const std::string& where) {
  throw Error("cache header", std::to_string(listed) + " bytes of tables",
              std::to_string(available) + " bytes (the rest of the file)", where);
}

// The first bytes of a file that is not a cache, printable characters as they are.
std::string Printable(std::span<const std::byte> bytes) {
  std::string text = "\"";
  for (std::byte b : bytes) {
    char c = static_cast<char>(b);
    if (c >= 0x20 && c < 0x7f) {
      text += c;
    } else {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\x%02x", static_cast<unsigned>(b));
      text += escape;
    }
  }
  return text + "\"";
}

void PutU32(std::vector<std::byte>& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(std::byte(v >> (8 * i)));
}
void PutU64(std::vector<std::byte>& out, uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(std::byte(v >> (8 * i)));
}
void SetU64(std::vector<std::byte>& out, size_t offset, uint64_t v) {
  for (int i = 0; i < 8; ++i) out[offset + i] = std::byte(v >> (8 * i));
}
void PutString(std::vector<std::byte>& out, const std::string& s) {
  PutU32(out, static_cast<uint32_t>(s.size()));
  auto bytes = std::as_bytes(std::span(s));
  out.insert(out.end(), bytes.begin(), bytes.end());
}

// Reads the header section; every read is bounds-checked because a header that passed its
// checksum can still have been written by a buggy or malicious program.
class Cursor {
 public:
  Cursor(std::span<const std::byte> bytes, std::string where)
      : bytes_(bytes), where_(std::move(where)) {}

  uint32_t U32() { return static_cast<uint32_t>(Little(Take(4))); }
  uint64_t U64() { return Little(Take(8)); }
  std::string String() {
    auto bytes = Take(U32());
    return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  }
  size_t remaining() const { return bytes_.size() - position_; }

 private:
  std::span<const std::byte> Take(size_t count) {
    if (count > remaining()) {
      throw Error("cache header", std::to_string(bytes_.size()) + " bytes",
                  "room for its fields (reading " + std::to_string(count) + " bytes at offset " +
                      std::to_string(kPrefixBytes + position_) + ")",
                  where_);
    }
    position_ += count;
    return bytes_.subspan(position_ - count, count);
  }
  static uint64_t Little(std::span<const std::byte> bytes) {
    uint64_t v = 0;
    for (size_t i = bytes.size(); i-- > 0;) v = v << 8 | std::to_integer<uint64_t>(bytes[i]);
    return v;
  }

  std::span<const std::byte> bytes_;
  size_t position_ = 0;
  std::string where_;
};

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

// The cache file, opened only if it is a regular one: O_NONBLOCK keeps a FIFO at its name from
// blocking the open (the cache is optional; a command must not hang on it).
File OpenRegularFile(const std::filesystem::path& path, const std::string& where) {
  int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    throw Error("cache file", where,
                std::string("an existing table cache (") + std::strerror(errno) + ")", where);
  }
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd);
    throw Error("cache file", where, std::string("a regular file, not ") + FileKindName(info.st_mode), where);
  }
  File file(::fdopen(fd, "rb"), &std::fclose);
  if (!file) {
    ::close(fd);
    throw Error("cache file", where, std::string("a readable file (") + std::strerror(errno) + ")", where);
  }
  return file;
}

void ReadExactly(std::FILE* file, std::byte* data, size_t count, const std::string& where) {
  if (std::fread(data, 1, count, file) != count) {
    const char* reason = std::ferror(file) ? std::strerror(errno) : "unexpected end of file";
    throw Error("cache file", where, std::string("a readable file (") + reason + ")", where);
  }
}

// Magic first (is this a cache at all?), then version (can we read its layout?), then the
// recorded size against the real one, so truncation is found before reading further.
uint64_t CheckPrefix(std::span<const std::byte> prefix, uint64_t actual_bytes,
                     const std::string& where) {
  if (prefix.size() >= sizeof kMagic && std::memcmp(prefix.data(), kMagic, sizeof kMagic) != 0) {
    throw Error("cache magic", Printable(prefix.first(sizeof kMagic)),
                "\"AERIALT\\x00\" (this is not an aerial table cache)", where);
  }
  if (prefix.size() < kPrefixBytes) {
    throw Error("cache size", std::to_string(actual_bytes) + " bytes",
                "at least " + std::to_string(kPrefixBytes + kChecksumBytes) + " bytes (truncated)",
                where);
  }
  Cursor fields(prefix.subspan(sizeof kMagic), where);
  uint32_t version = fields.U32();
  uint64_t header_bytes = fields.U32();
  uint64_t file_bytes = fields.U64();
  if (version != kTableCacheVersion) {
    throw Error("cache version", std::to_string(version),
                std::to_string(kTableCacheVersion) + " (made by another aerial version)", where);
  }
  if (actual_bytes != file_bytes) {
    throw Error("cache size", std::to_string(actual_bytes) + " bytes",
                std::to_string(file_bytes) + " bytes as recorded in the file" +
                    (actual_bytes < file_bytes ? " (truncated)" : " (trailing bytes)"),
                where);
  }
  if (kPrefixBytes + header_bytes + kChecksumBytes > file_bytes) {
    throw Error("cache header", std::to_string(header_bytes) + " bytes",
                "at most " + std::to_string(file_bytes - kPrefixBytes - kChecksumBytes) +
                    " bytes (the file size)",
                where);
  }
  return header_bytes;
}

// Parses a header section that passed its checksum: the key, then the table entries, which must
// exactly fill payload_bytes. Returns the tables' stored checksums.
std::vector<uint64_t> ParseHeader(std::span<const std::byte> section, uint64_t payload_bytes,
                                  const TableCacheKey& expected, TableCache& cache,
                                  const std::string& where) {
  Cursor cursor(section, where);
  cache.key.atmosphere_hash = cursor.U64();
  cache.key.options_hash = cursor.U64();
  if (cache.key != expected) {
    throw Error("cache key", Describe(cache.key),
                Describe(expected) + " (the cache was made for another parameter set)", where);
  }
  cache.description = cursor.String();
  uint32_t count = cursor.U32();
  std::vector<uint64_t> checksums;
  uint64_t listed = 0;
  for (uint32_t i = 0; i < count; ++i) {
    CachedTable& t = cache.tables.emplace_back();
    t.name = cursor.String();
    t.width = cursor.U32();
    t.height = cursor.U32();
    t.depth = cursor.U32();
    t.format = static_cast<TexelFormat>(cursor.U32());
    uint64_t texel_bytes = cursor.U64();
    checksums.push_back(cursor.U64());
    if (texel_bytes == 0 || texel_bytes != ExpectedTexelBytes(t))
      ThrowBadShape(t, texel_bytes, where);
    // Compared before adding, so a corrupt size cannot wrap the sum around.
    if (texel_bytes > payload_bytes - listed)
      ThrowPayloadMismatch(listed + texel_bytes, payload_bytes, where);
    listed += texel_bytes;
  }
  if (listed != payload_bytes) ThrowPayloadMismatch(listed, payload_bytes, where);
  if (cursor.remaining() != 0) {
    throw Error("cache header", std::to_string(cursor.remaining()) + " unread bytes",
                "no bytes after the last table entry", where);
  }
  return checksums;
}

}  // namespace

uint32_t TexelBytes(TexelFormat format) {
  switch (format) {
    case TexelFormat::kRgba32f: return 16;
    case TexelFormat::kRgba16f: return 8;
  }
  return 0;
}

void WriteTableCache(const std::filesystem::path& path, const TableCache& cache) {
  const std::string where = path.string();
  std::vector<std::byte> file(std::as_bytes(std::span(kMagic)).begin(),
                              std::as_bytes(std::span(kMagic)).end());
  PutU32(file, kTableCacheVersion);
  PutU32(file, 0);  // header_bytes, set below.
  PutU64(file, 0);  // file_bytes, set below.
  PutU64(file, cache.key.atmosphere_hash);
  PutU64(file, cache.key.options_hash);
  PutString(file, cache.description);
  PutU32(file, static_cast<uint32_t>(cache.tables.size()));
  uint64_t payload_bytes = 0;
  for (const CachedTable& t : cache.tables) {
    uint64_t expected = ExpectedTexelBytes(t);
    if (expected == 0 || expected != t.texels.size()) ThrowBadShape(t, t.texels.size(), where);
    PutString(file, t.name);
    for (uint32_t v : {t.width, t.height, t.depth, static_cast<uint32_t>(t.format)})
      PutU32(file, v);
    PutU64(file, t.texels.size());
    PutU64(file, Checksum(t.texels));
    payload_bytes += t.texels.size();
  }
  uint64_t header_bytes = file.size() - kPrefixBytes;
  if (header_bytes > UINT32_MAX) {
    throw Error("cache header", std::to_string(header_bytes) + " bytes", "< 4 GiB", where);
  }
  uint64_t file_bytes = kPrefixBytes + header_bytes + kChecksumBytes + payload_bytes;
  for (int i = 0; i < 4; ++i) file[12 + i] = std::byte(header_bytes >> (8 * i));
  SetU64(file, 16, file_bytes);
  PutU64(file, Checksum(file));
  file.reserve(file_bytes);
  for (const CachedTable& t : cache.tables)
    file.insert(file.end(), t.texels.begin(), t.texels.end());
  WriteFileAtomically(path, file);
}

TableCache ReadTableCache(const std::filesystem::path& path, const TableCacheKey& expected) {
  const std::string where = path.string();
  File file = OpenRegularFile(path, where);
  struct stat info;
  if (::fstat(::fileno(file.get()), &info) != 0)
    throw Error("cache file", where, std::string("a readable file (") + std::strerror(errno) + ")", where);
  uint64_t actual_bytes = static_cast<uint64_t>(info.st_size);
  if (actual_bytes > kMaxTableCacheBytes) {
    throw Error("cache size", std::to_string(actual_bytes) + " bytes",
                "at most " + std::to_string(kMaxTableCacheBytes) + " bytes (no table set is larger)",
                where);
  }

  std::vector<std::byte> header(std::min(actual_bytes, kPrefixBytes));
  ReadExactly(file.get(), header.data(), header.size(), where);
  uint64_t header_bytes = CheckPrefix(header, actual_bytes, where);

  // The header is verified by its checksum before any of it is believed.
  header.resize(kPrefixBytes + header_bytes + kChecksumBytes);
  ReadExactly(file.get(), header.data() + kPrefixBytes, header_bytes + kChecksumBytes, where);
  std::span<const std::byte> all(header);
  uint64_t stored = Cursor(all.last(kChecksumBytes), where).U64();
  uint64_t computed = Checksum(all.first(kPrefixBytes + header_bytes));
  if (stored != computed) {
    throw Error("cache header checksum", Hex(computed), Hex(stored) + " as stored (corrupt header)",
                where);
  }
  TableCache cache;
  std::vector<uint64_t> checksums =
      ParseHeader(all.subspan(kPrefixBytes, header_bytes), actual_bytes - header.size(), expected,
                  cache, where);

  // Each table has its own checksum, so a message names the damaged one.
  for (size_t i = 0; i < cache.tables.size(); ++i) {
    CachedTable& t = cache.tables[i];
    t.texels.resize(ExpectedTexelBytes(t));
    ReadExactly(file.get(), t.texels.data(), t.texels.size(), where);
    uint64_t actual = Checksum(t.texels);
    if (actual != checksums[i]) {
      throw Error("cache table \"" + t.name + "\" checksum", Hex(actual),
                  Hex(checksums[i]) + " as stored (corrupt texels)", where);
    }
  }
  // The checksums say the texels are as written, not that they are numbers: the same check as
  // after a precompute.
  if (std::optional<NonFiniteTexel> bad = FindNonFiniteTexel(cache)) {
    throw Error("cache table \"" + bad->table + "\"", bad->description,
                "finite texels (tables written with a NaN or infinity in them are never used)", where);
  }
  return cache;
}

}  // namespace aerial
