// tinygltf as matc builds it, for every source that includes it (the macros change its classes'
// defaults, so all must agree): no image decoding or writing (matc reads materials, not pixels)
// and no file system of its own (gltf_asset.cpp gives it callbacks that stay inside the asset's
// folder).
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
#include <fstream>  // tinygltf's writer uses it without including it when TINYGLTF_NO_FS is set

#include <tiny_gltf.h>
