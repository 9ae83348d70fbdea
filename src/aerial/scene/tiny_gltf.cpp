// The one translation unit that compiles tinygltf's implementation (a header-only library; see
// tiny_gltf_config.h for the macros). /usr/include is a system directory, so its warnings stay
// quiet under -Wall -Wextra.
#define TINYGLTF_IMPLEMENTATION
#include "aerial/scene/tiny_gltf_config.h"
