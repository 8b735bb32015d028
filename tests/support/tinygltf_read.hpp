// Test helper: tinygltf for reading outputs back, configured as the library compiles it (no image
// decoding or writing, no external images); the library's write_gltf.cpp holds the implementation.
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
