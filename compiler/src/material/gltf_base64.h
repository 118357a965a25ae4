// Base64 as glTF's data URIs write it (tinygltf's encoder, the one matc's glTF reader decodes
// with): for binary data a glTF extension carries in its JSON.
#pragma once

#include <string>
#include <string_view>

namespace matc {

std::string gltf_base64(std::string_view bytes);

}  // namespace matc
