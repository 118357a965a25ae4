// tinygltf's implementation (Debian's libtinygltf-dev ships it in its header), compiled into the
// library so that the native and the WebAssembly builds read glTF with the same code, configured
// as tinygltf_config.h says.
#define TINYGLTF_IMPLEMENTATION
#include "tinygltf_config.h"
