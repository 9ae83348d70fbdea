#pragma once
// The container of a binary glTF (.glb), checked before tinygltf parses it (glTF 2.0 spec,
// "Binary glTF Layout": a 12-byte header "glTF", version, length; then chunks of a 4-byte length,
// a 4-byte type and that many bytes, the JSON chunk first and an optional BIN chunk). tinygltf
// checks the BIN chunk's length without its 8-byte chunk header and copies up to 8 bytes past the
// end of the file; here every length must fit in the file as read.
#include <string>
#include <string_view>
#include <vector>

namespace aerial {

// The JSON chunk of a .glb whose header and chunk lengths fit in bytes. Throws
// Error("GLB header" / "GLB length" / "GLB chunk[i] length", value, allowed, where) otherwise.
std::string_view CheckedGlbJson(const std::vector<unsigned char>& bytes, const std::string& where);

}  // namespace aerial
