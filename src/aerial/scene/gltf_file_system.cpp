#include "aerial/scene/gltf_file_system.h"

#include <algorithm>
#include <cctype>

#include "aerial/core/bounded_file.h"

namespace aerial {
namespace {

// RFC 3986, 3.1: ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) ":".
bool HasScheme(const std::string& uri) {
  size_t colon = uri.find(':');
  if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(uri[0])))
    return false;
  return std::all_of(uri.begin(), uri.begin() + colon, [](unsigned char c) {
    return std::isalnum(c) || c == '+' || c == '-' || c == '.';
  });
}

// Whether path lies in folder, both canonical.
bool IsWithin(const std::filesystem::path& folder, const std::filesystem::path& path) {
  auto [end, ignored] = std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
  return end == folder.end();
}

}  // namespace

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

std::string GltfFileSystem::UriOf(const std::string& path) const {
  if (folder_.empty()) return path;
  std::string prefix = folder_.back() == '/' ? folder_ : folder_ + "/";  // as tinygltf joins them
  return path.starts_with(prefix) ? path.substr(prefix.size()) : path;
}

void GltfFileSystem::CheckInsideFolder(const std::string& uri, const std::filesystem::path& path,
                                       const std::string& field) const {
  std::filesystem::path folder = folder_.empty() ? "." : folder_;
  std::string inside = "a relative path to a file inside the model's folder " + folder.string();
  if (uri.empty() || uri.front() == '/') throw Error(field, uri, inside + " (not an absolute path)");
  if (uri.find('\0') != std::string::npos) throw Error(field, uri, inside + " (without a NUL character)");
  if (HasScheme(uri)) throw Error(field, uri, inside + " or a data: URI (no other scheme)");
  std::error_code folder_error, path_error;
  std::filesystem::path real_folder = std::filesystem::weakly_canonical(folder, folder_error);
  std::filesystem::path real_path = std::filesystem::weakly_canonical(path, path_error);
  if (folder_error || path_error || !IsWithin(real_folder, real_path))
    throw Error(field, uri, inside + " (after \"..\" and symbolic links)");
}

tinygltf::FsCallbacks GltfFileSystem::Callbacks() {
  return {&FileExists, &ExpandFilePath, &ReadWholeFile, &WriteWholeFile, this};
}

void GltfFileSystem::RethrowFailure() const {
  if (failure_) throw *failure_;
}

void GltfFileSystem::RethrowRefusedBuffer() const {
  // tinygltf appends a buffer once it is accepted: the one just read is not there yet.
  if (last_read_buffer_ && *last_read_buffer_ == model_.buffers.size()) {
    throw Error("buffers[" + std::to_string(*last_read_buffer_) + "].byteLength", "(as written)",
                "the size of its file " + last_read_uri_ + ", and at least 1 byte (sizes read "
                "from files are not shown)");
  }
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
  size_t index = files.model_.buffers.size();
  std::string field = "buffers[" + std::to_string(index) + "].uri";
  try {
    std::string uri = files.UriOf(path);
    files.CheckInsideFolder(uri, path, field);
    *out = files.Read(path, field);
    files.last_read_buffer_ = index;
    files.last_read_uri_ = uri;
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
