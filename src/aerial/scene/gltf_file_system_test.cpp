#include "aerial/scene/gltf_file_system.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/scratch_directory.h"

namespace aerial {
namespace {

class GltfFileSystemTest : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(dir_ / "60.bin") << std::string(60, 'x'); }

  testing::ScratchDirectory dir_{"gltf_file_system"};
};

TEST_F(GltfFileSystemTest, FilesShareOneBudget) {
  tinygltf::Model model;
  GltfFileSystem files(model, dir_.path().string(), 100);
  EXPECT_EQ(files.ReadModelFile(dir_ / "60.bin").size(), 60u);
  // 40 bytes are left: the same 60-byte file no longer fits.
  try {
    files.ReadModelFile(dir_ / "60.bin");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "glTF file");
    EXPECT_EQ(e.allowed(),
              "a regular file of at most 40 bytes (it has 60); a glTF model and its buffers share "
              "100 bytes");
  }
}

TEST_F(GltfFileSystemTest, FailedBufferReadIsNamedAndRethrown) {
  tinygltf::Model model;
  model.buffers.resize(2);  // tinygltf has read buffers 0 and 1: this read is buffers[2]
  GltfFileSystem files(model, dir_.path().string(), 100);
  tinygltf::FsCallbacks callbacks = files.Callbacks();
  std::vector<unsigned char> out;
  std::string error;
  std::string path = (dir_ / "none.bin").string();
  EXPECT_TRUE(callbacks.FileExists(path, callbacks.user_data)) << "left to ReadWholeFile";
  EXPECT_FALSE(callbacks.ReadWholeFile(&out, &error, path, callbacks.user_data));
  EXPECT_NE(error.find("buffers[2].uri"), std::string::npos) << error;
  try {
    files.RethrowFailure();
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "buffers[2].uri");
    EXPECT_EQ(e.value(), path);
  }
}

TEST_F(GltfFileSystemTest, BufferReadCountsAgainstTheBudget) {
  tinygltf::Model model;
  GltfFileSystem files(model, dir_.path().string(), 100);
  tinygltf::FsCallbacks callbacks = files.Callbacks();
  std::vector<unsigned char> out;
  std::string error;
  std::string path = (dir_ / "60.bin").string();
  EXPECT_TRUE(callbacks.ReadWholeFile(&out, &error, path, callbacks.user_data)) << error;
  EXPECT_EQ(out.size(), 60u);
  EXPECT_FALSE(callbacks.ReadWholeFile(&out, &error, path, callbacks.user_data));
  EXPECT_THROW(files.RethrowFailure(), Error);
}

}  // namespace
}  // namespace aerial
