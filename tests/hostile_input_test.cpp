// Hostile input files: each is refused with an aerial::Error naming the field and the
// value, and by the command with exit status 1 and that message; never a crash, a hang, an
// out-of-bounds read or a raw std:: exception. The crafted files are in tests/data/hostile/
// (its README says what each one does); huge, deep and special files (FIFOs, devices,
// directories) are made here at run time.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "aerial/core/input_limits.h"
#include "aerial/error.h"
#include "aerial/scene/gltf_loader.h"
#include "command_run.h"
#include "scratch_directory.h"

namespace aerial::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kHostile = fs::path(AERIAL_SOURCE_DIR) / "tests/data/hostile";

// The Error LoadGltfMesh(path) throws.
Error GltfError(const fs::path& path) {
  try {
    LoadGltfMesh(path, "hostile");
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "loaded " << path;
  return Error("", "", "");
}

struct CraftedGltf {
  std::string file;
  std::string field;
  std::string value;
};

void PrintTo(const CraftedGltf& input, std::ostream* out) { *out << input.file; }

class HostileGltfFile : public ::testing::TestWithParam<CraftedGltf> {};

TEST_P(HostileGltfFile, IsRefusedNamingTheGltfField) {
  fs::path path = kHostile / GetParam().file;
  Error e = GltfError(path);
  EXPECT_EQ(e.field(), GetParam().field) << e.what();
  EXPECT_EQ(e.value(), GetParam().value) << e.what();
  EXPECT_EQ(e.where(), path.string());
}

INSTANTIATE_TEST_SUITE_P(
    CraftedFiles, HostileGltfFile,
    ::testing::Values(
        CraftedGltf{"view_offset_wraps.gltf", "bufferViews[0].byteOffset", "18446744073709551612"},
        CraftedGltf{"accessor_offset_wraps.gltf", "accessors[0].byteOffset", "18446744073709551604"},
        CraftedGltf{"count_near_2_63.gltf", "accessors[0].count", "9223372036854775808"},
        CraftedGltf{"stride_below_element.gltf", "bufferViews[0].byteStride", "4"},
        CraftedGltf{"view_past_buffer.gltf", "bufferViews[0].byteLength", "40"},
        CraftedGltf{"position_as_short.gltf", "accessors[0].componentType", "5123"},
        CraftedGltf{"strided_count_past_view.gltf", "accessors[0].count", "3"},
        // A DAG of 2^40 paths, an index and vertices never shown, a GLB chunk lie.
        CraftedGltf{"node_dag.gltf", "nodes[40]", "reached twice"},
        CraftedGltf{"index_past_vertices.gltf", "meshes[0].primitives[0].indices", "element 2"},
        CraftedGltf{"translation_1e308.gltf", "meshes[0].primitives[0].POSITION",
                    "vertex 0 after the node transforms"},
        CraftedGltf{"nan_vertex.gltf", "meshes[0].primitives[0].POSITION",
                    "vertex 2 after the node transforms"},
        CraftedGltf{"bin_chunk_past_end.glb", "GLB chunk[1] length", "44"}),
    [](const ::testing::TestParamInfo<CraftedGltf>& info) { return "case" + std::to_string(info.index); });

TEST(HostileGltf, CountBoundFollowsTheStride) {
  // 36 bytes hold elements of 12 bytes every 16 at 0 and 16; a third would end at byte 44.
  EXPECT_EQ(GltfError(kHostile / "strided_count_past_view.gltf").allowed().rfind("at most 2,", 0), 0u);
}

TEST(HostileGltf, DirectoryAsBufferNamesTheBuffer) {
  Error e = GltfError(kHostile / "buffer_uri_dot.gltf");
  EXPECT_EQ(e.field(), "buffers[1].uri");
  EXPECT_EQ(e.value(), (kHostile / ".").string());
  EXPECT_EQ(e.allowed(), "a regular file, not a directory");
}

TEST(HostileGltf, LongDataUriIsShortenedInTheMessage) {
  // The URI is 3,037 characters. The message holds the path, kMaxShownBytes of tinygltf's report
  // of the URI and under 100 characters of its own words.
  fs::path path = kHostile / "long_data_uri.gltf";
  Error e = GltfError(path);
  std::string message = e.what();
  EXPECT_EQ(e.field(), "glTF file");
  EXPECT_LT(message.size(), path.string().size() + kMaxShownBytes + 100) << message;
  EXPECT_NE(message.find("\u2026 ("), std::string::npos) << message;
}

// Files made at run time in a fresh directory.
class HostileFiles : public ::testing::Test {
 protected:
  fs::path Write(const std::string& name, const std::string& bytes) {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return dir_ / name;
  }
  fs::path Fifo(const std::string& name) {
    fs::path path = dir_ / name;
    EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0);
    return path;
  }
  // A file of size bytes that takes no disk space (sparse).
  fs::path Sparse(const std::string& name, uintmax_t size) {
    fs::path path = Write(name, "");
    fs::resize_file(path, size);
    return path;
  }
  // A .gltf whose only buffer is the file uri (no meshes: tinygltf reads the buffers first).
  fs::path GltfWithBuffer(const std::string& uri, size_t byte_length) {
    return Write("model.gltf",
                 R"({"asset": {"version": "2.0"}, "buffers": [{"uri": ")" + uri +
                     R"(", "byteLength": )" + std::to_string(byte_length) + "}]}");
  }

  // A message without the scratch directory's path (whose pid may hold any digit).
  std::string WithoutScratchPath(std::string message) const {
    for (size_t at; (at = message.find(dir_.path().string())) != std::string::npos;)
      message.erase(at, dir_.path().string().size());
    return message;
  }

  ScratchDirectory dir_{"hostile"};
};

// A buffer must be a file inside the model's folder, refused before it is read. The
// model is in dir_/model/, beside dir_/secret.bin (a file it must not reach).
class BufferOutsideTheFolder : public HostileFiles, public ::testing::WithParamInterface<std::string> {};

TEST_P(BufferOutsideTheFolder, IsRefusedNamingTheBuffer) {
  Write("secret.bin", "0123456");  // 7 bytes: no message may say so
  fs::create_directory(dir_ / "model");
  fs::create_symlink(dir_ / "secret.bin", dir_ / "model" / "link.bin");
  fs::path model = Write("model/model.gltf",
                         R"({"asset": {"version": "2.0"}, "buffers": [{"uri": ")" + GetParam() +
                             R"(", "byteLength": 36}]})");
  Error e = GltfError(model);
  EXPECT_EQ(e.field(), "buffers[0].uri") << e.what();
  EXPECT_NE(e.allowed().find("inside the model's folder"), std::string::npos) << e.what();
  EXPECT_EQ(WithoutScratchPath(e.what()).find('7'), std::string::npos) << e.what();
}

INSTANTIATE_TEST_SUITE_P(Uris, BufferOutsideTheFolder,
                         ::testing::Values("../secret.bin", "..%2Fsecret.bin", "link.bin",
                                           "/etc/passwd", "file:///etc/passwd"));

TEST_F(HostileFiles, BufferSizeMismatchDoesNotShowTheFileSize) {
  Write("data.bin", "0123456");
  Error e = GltfError(GltfWithBuffer("data.bin", 36));
  EXPECT_EQ(e.field(), "buffers[0].byteLength") << e.what();
  EXPECT_EQ(WithoutScratchPath(e.what()).find('7'), std::string::npos) << e.what();
}

// JSON nesting levels deep, inside an otherwise valid glTF.
std::string DeepGltfJson(size_t levels) {
  return R"({"asset": {"version": "2.0"}, "extras": )" + std::string(levels, '[') +
         std::string(levels, ']') + "}";
}

TEST_F(HostileFiles, DeeplyNestedGltfIsRefusedBeforeParsing) {
  fs::path path = Write("deep.gltf", DeepGltfJson(100000));
  Error e = GltfError(path);
  EXPECT_EQ(e.field(), "JSON nesting");
  EXPECT_EQ(e.value(), "100001 levels");  // the extras and the root object
  EXPECT_EQ(e.where(), path.string());
}

TEST_F(HostileFiles, DeeplyNestedGlbIsRefusedBeforeParsing) {
  // glTF 2.0 spec, "Binary glTF Layout": header, then the JSON chunk padded with spaces.
  std::string json = DeepGltfJson(100000);
  json.resize((json.size() + 3) / 4 * 4, ' ');
  std::string glb = "glTF";
  auto u32 = [&](uint32_t value) { glb.append(reinterpret_cast<const char*>(&value), 4); };
  u32(2);
  u32(static_cast<uint32_t>(12 + 8 + json.size()));
  u32(static_cast<uint32_t>(json.size()));
  u32(0x4E4F534A);  // "JSON"
  fs::path path = Write("deep.glb", glb + json);
  Error e = GltfError(path);
  EXPECT_EQ(e.field(), "JSON nesting");
  EXPECT_EQ(e.value(), "100001 levels");
}

TEST_F(HostileFiles, FifoAsBufferIsRefusedWithoutBlocking) {
  fs::path fifo = Fifo("buffer.bin");
  ::alarm(10);  // should opening the FIFO regress, the test's process ends instead of hanging
  Error e = GltfError(GltfWithBuffer("buffer.bin", 36));
  ::alarm(0);
  EXPECT_EQ(e.field(), "buffers[0].uri");
  EXPECT_EQ(e.value(), fifo.string());
  EXPECT_EQ(e.allowed(), "a regular file, not a FIFO (named pipe)");
}

TEST_F(HostileFiles, OversizeBufferIsRefusedBeforeReading) {
  fs::path big = Sparse("big.bin", kMaxGltfBytes + 1);
  Error e = GltfError(GltfWithBuffer("big.bin", kMaxGltfBytes + 1));
  EXPECT_EQ(e.field(), "buffers[0].uri");
  EXPECT_EQ(e.value(), big.string());
  EXPECT_NE(e.allowed().find("a glTF model and its buffers share " + std::to_string(kMaxGltfBytes) +
                             " bytes"),
            std::string::npos)
      << e.allowed();
}

// A 20 MB `extras` array would peak at 1.96 GB RSS whatever --max-memory-mib says. The
// JSON parse is estimated (here 1,000,001 values, 200 MB) against the budget before it is made.
TEST_F(HostileFiles, JsonParseBeyondTheBudgetIsRefusedBeforeParsing) {
  std::string zeros;
  for (int i = 0; i < 1000000; ++i) zeros += "0,";
  fs::path path = Write("extras.gltf", R"({"asset": {"version": "2.0"}, "extras": [)" + zeros + "0]}");
  try {
    LoadGltfMesh(path, "extras", MemoryBudget{100 * kMiB, "--max-memory-mib 100"});
    FAIL() << "loaded";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "glTF model") << e.what();
    EXPECT_NE(e.allowed().find("> budget 100.0 MiB (--max-memory-mib 100)"), std::string::npos) << e.what();
  }
}

TEST_F(HostileFiles, OversizeGltfIsRefusedBeforeReading) {
  Error e = GltfError(Sparse("big.gltf", kMaxGltfBytes + 1));
  EXPECT_EQ(e.field(), "glTF file");
  EXPECT_EQ(e.allowed(), "a regular file of at most " + std::to_string(kMaxGltfBytes) +
                             " bytes (it has " + std::to_string(kMaxGltfBytes + 1) + ")");
}

const char* kOut = "/tmp/aerial-hostile-test.png";
const std::string kRender = std::string("render --small-tables --quiet --out ") + kOut;
const std::string kPrecompute = "precompute --small-tables --quiet --no-cache";

// The command: exit status 1, a message naming the option and the reason, and no image. These
// refusals come before any GPU work and take well under a second; `timeout 30` turns a read that
// blocks or never ends (the old /dev/zero) into a failure (status 124) instead of a hang.
void ExpectRefused(const std::string& arguments, const std::string& field,
                   const std::string& reason) {
  fs::remove(kOut);
  CommandRun run = RunAerial(arguments, "timeout 30");
  EXPECT_FALSE(fs::exists(kOut)) << arguments;
  EXPECT_EQ(run.exit_code, 1) << arguments << "\n" << run.err;
  EXPECT_NE(run.err.find(field), std::string::npos) << "no " << field << " in:\n" << run.err;
  EXPECT_NE(run.err.find(reason), std::string::npos) << "no " << reason << " in:\n" << run.err;
}

TEST_F(HostileFiles, CommandRefusesDevZero) {
  ExpectRefused(kPrecompute + " --atmosphere /dev/zero", "--atmosphere = /dev/zero",
                "not a character device");
  ExpectRefused(kRender + " --scene /dev/zero", "--scene = /dev/zero", "not a character device");
}

TEST_F(HostileFiles, CommandRefusesAFifoWithoutBlocking) {
  fs::path fifo = Fifo("scene.toml");
  ExpectRefused(kRender + " --scene " + fifo.string(), "--scene = " + fifo.string(),
                "not a FIFO (named pipe)");
  ExpectRefused("view --camera-path " + fifo.string(), "--camera-path = " + fifo.string(),
                "not a FIFO (named pipe)");
}

TEST_F(HostileFiles, CommandRefusesADirectory) {
  ExpectRefused(kPrecompute + " --atmosphere " + dir_.path().string(),
                "--atmosphere = " + dir_.path().string(),
                "not a directory");
}

TEST_F(HostileFiles, CommandRefusesAFileOverTheTomlCap) {
  fs::path big = Sparse("big.toml", kMaxTomlFileBytes + 1);
  ExpectRefused(kRender + " --scene " + big.string(), "--scene = " + big.string(),
                "at most " + std::to_string(kMaxTomlFileBytes) + " bytes");
}

TEST(HostileCommand, SceneWithAWrappingGltfNamesTheGltfField) {
  ExpectRefused(kRender + " --scene " + (kHostile / "scene_with_wrapping_gltf.toml").string(),
                "mesh[0].gltf", "bufferViews[0].byteOffset = 18446744073709551612");
}

TEST(HostileCommand, CameraPathWithoutAKeyNamesTheKey) {
  ExpectRefused("view --camera-path " + (kHostile / "camera_path_missing_yaw.toml").string(),
                "keyframe[1].yaw_deg = missing", "a number (degrees)");
}

}  // namespace
}  // namespace aerial::testing
