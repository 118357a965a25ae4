// The files under compiler/data/, compiled in by matc_embed_files() (see compiler/CMakeLists.txt).
#pragma once

#include <span>
#include <string_view>

#include "base/embedded_file.h"

namespace matc::embedded_data {

std::span<const EmbeddedFile> files();

// The bytes of one embedded file; throws std::logic_error if it was not embedded (a build bug).
std::string_view file(std::string_view path);

}  // namespace matc::embedded_data
