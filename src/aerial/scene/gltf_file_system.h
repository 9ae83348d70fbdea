#pragma once
// The files of one glTF model, read for tinygltf through ReadBoundedFile (core/bounded_file.h):
// the .gltf or .glb itself (ReadModelFile) and its external buffers (tinygltf calls Callbacks()
// for those). All of them together may hold at most max_bytes (kMaxGltfBytes), so a model
// cannot make the program read more than that by naming the same big file in many buffers.
//
// A buffer's file must lie inside the model's folder: a URI that is absolute, has a scheme
// (file:, http:; tinygltf decodes data: URIs itself and never asks for them) or resolves outside
// the folder (after tinygltf's percent-decoding, "..", and symlinks) is refused before anything
// is read, so a model cannot read, and its messages cannot disclose, any other file the user can
// read. Images are never read (TINYGLTF_NO_EXTERNAL_IMAGE).
//
// A buffer's file that cannot be read is an Error naming the buffer ("buffers[1].uri"). It cannot
// cross tinygltf, which expects a bool, so it is kept and thrown by RethrowFailure() once
// tinygltf returns.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "aerial/error.h"
#include "aerial/scene/tiny_gltf_config.h"

namespace aerial {

class GltfFileSystem {
 public:
  // model is the one tinygltf fills: the number of buffers it holds so far is the index of the
  // buffer being read, as tinygltf appends each buffer once its file is read. folder is the
  // base directory given to tinygltf (the model's folder, "" for the current directory).
  GltfFileSystem(const tinygltf::Model& model, std::string folder, size_t max_bytes)
      : model_(model), folder_(std::move(folder)), left_bytes_(max_bytes), max_bytes_(max_bytes) {}

  // The model's own file (field "glTF file").
  std::vector<unsigned char> ReadModelFile(const std::filesystem::path& path);

  // For TinyGLTF::SetFsCallbacks. Only valid while this object lives.
  tinygltf::FsCallbacks Callbacks();

  // Throws the Error a callback met, if any.
  void RethrowFailure() const;

  // After tinygltf failed: when it refused the buffer file just read (a byteLength other than
  // the file's size, or an empty file), throws an Error naming that buffer. tinygltf's own
  // message would print the file's size, which is not the user's to learn from a model.
  void RethrowRefusedBuffer() const;

 private:
  std::vector<unsigned char> Read(const std::filesystem::path& path, const std::string& field);
  // The URI as tinygltf decoded it, from the path it joined to the folder.
  std::string UriOf(const std::string& path) const;
  void CheckInsideFolder(const std::string& uri, const std::filesystem::path& path,
                         const std::string& field) const;

  static bool FileExists(const std::string& path, void* self);
  static std::string ExpandFilePath(const std::string& path, void* self);
  static bool ReadWholeFile(std::vector<unsigned char>* out, std::string* err,
                            const std::string& path, void* self);
  static bool WriteWholeFile(std::string* err, const std::string& path,
                             const std::vector<unsigned char>& contents, void* self);

  const tinygltf::Model& model_;
  std::string folder_;
  size_t left_bytes_, max_bytes_;
  std::optional<Error> failure_;
  std::optional<size_t> last_read_buffer_;  // the index of the buffer last read from a file
  std::string last_read_uri_;
};

}  // namespace aerial
