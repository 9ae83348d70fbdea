#include "aerial/scene/gltf_file_system.h"

#include "aerial/core/bounded_file.h"

namespace aerial {

std::vector<unsigned char> GltfFileSystem::ReadModelFile(const std::filesystem::path& path) {
  return Read(path, "glTF file");
}

std::vector<unsigned char> GltfFileSystem::Read(const std::filesystem::path& path,
                                                const std::string& field) {
  std::string note = left_bytes_ == max_bytes_ ? ""
                                               : "; a glTF model and its buffers share " +
                                                     std::to_string(max_bytes_) + " bytes";
  std::vector<unsigned char> bytes = ReadBoundedFile(path, field, left_bytes_, note);
  left_bytes_ -= bytes.size();
  return bytes;
}

tinygltf::FsCallbacks GltfFileSystem::Callbacks() {
  return {&FileExists, &ExpandFilePath, &ReadWholeFile, &WriteWholeFile, this};
}

void GltfFileSystem::RethrowFailure() const {
  if (failure_) throw *failure_;
}

// tinygltf looks for a buffer's file beside the model, then in the current directory, asking
// FileExists of each. Saying yes makes it read the one beside the model, so a missing file is
// reported by ReadBoundedFile, naming the buffer, and the current directory is never searched.
// (tinygltf's own FileExists opens the file, which blocks on a FIFO.)
bool GltfFileSystem::FileExists(const std::string&, void*) { return true; }

// URIs are not expanded (no "~" or environment variables), as in tinygltf's own callback.
std::string GltfFileSystem::ExpandFilePath(const std::string& path, void*) { return path; }

bool GltfFileSystem::ReadWholeFile(std::vector<unsigned char>* out, std::string* err,
                                   const std::string& path, void* self) {
  auto& files = *static_cast<GltfFileSystem*>(self);
  std::string field = "buffers[" + std::to_string(files.model_.buffers.size()) + "].uri";
  try {
    *out = files.Read(path, field);
    return true;
  } catch (const Error& e) {
    files.failure_ = e;
    if (err) *err += e.what();
    return false;
  }
}

// Loading never writes.
bool GltfFileSystem::WriteWholeFile(std::string* err, const std::string&,
                                    const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing is not supported";
  return false;
}

}  // namespace aerial
