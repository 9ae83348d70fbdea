#pragma once
// The kind of a file that is not a regular one, in words, for messages ("a FIFO (named pipe)").
#include <sys/stat.h>

namespace aerial {

// "a directory", "a FIFO (named pipe)", "a character device", "a block device", "a socket", or
// "a special file".
const char* FileKindName(mode_t mode);

}  // namespace aerial
