#pragma once
// tinygltf as this project builds it: geometry and materials only. Without these macros tinygltf
// would compile stb_image and stb_image_write into tiny_gltf.cpp, and src/aerial/image/ already
// defines stb_image_write's implementation (a second definition would clash at link time). Every
// file that includes tiny_gltf.h must go through this header: the macros change the layout of
// the TinyGLTF class, so all files must agree (one definition rule).
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
