#include "base/embedded_file.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "base/embedded_data.h"
#include "base/embedded_templates.h"

namespace matc {

std::string_view find_embedded_file(std::span<const EmbeddedFile> files, std::string_view path) {
  const auto found = std::find_if(files.begin(), files.end(),
                                  [&](const EmbeddedFile& f) { return f.path == path; });
  if (found == files.end()) throw std::logic_error("file not embedded: " + std::string(path));
  return found->bytes;
}

std::string_view embedded_data::file(std::string_view path) {
  return find_embedded_file(files(), path);
}

std::string_view embedded_templates::file(std::string_view path) {
  return find_embedded_file(files(), path);
}

}  // namespace matc
