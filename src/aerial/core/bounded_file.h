#pragma once
// The one way files that users name are read (configs, scenes, camera paths, glTF models and
// their buffers): whole, but never more than a cap (input_limits.h), and only regular files.
//
// A path with a NUL in it (possible in a TOML string or a glTF URI) is refused, since the system
// would read the file its first part names. A FIFO, a character device (/dev/zero), a socket or a
// directory is refused before it is opened, so a FIFO without a writer cannot block the program
// and /dev/zero cannot feed it forever. The size is checked before reading, and the read stops at max_bytes + 1 bytes, so a file that grows
// while it is read is refused too. Every failure throws
// Error(field, path, "a regular file ..." / "a readable file (<OS reason>)").
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace aerial {

// field names the input in messages ("scene file", or "buffers[1].uri"); cap_note, if
// any, ends the message for a file over the cap (where max_bytes comes from).
std::vector<unsigned char> ReadBoundedFile(const std::filesystem::path& path,
                                           const std::string& field, size_t max_bytes,
                                           const std::string& cap_note = "");

}  // namespace aerial
