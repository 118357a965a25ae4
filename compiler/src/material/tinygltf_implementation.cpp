// tinygltf's implementation (Debian's libtinygltf-dev ships it in its header), compiled into the
// library so that the native and the WebAssembly builds read glTF with the same code, configured
// as tinygltf_config.h says.
#define TINYGLTF_IMPLEMENTATION
#include "tinygltf_config.h"

#include "material/gltf_base64.h"

namespace matc {

std::string gltf_base64(std::string_view bytes) {
  return tinygltf::base64_encode(reinterpret_cast<const unsigned char*>(bytes.data()),
                                 static_cast<unsigned int>(bytes.size()));
}

}  // namespace matc
