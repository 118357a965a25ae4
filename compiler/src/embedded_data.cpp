#include "embedded_data.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace matc::embedded_data {

std::string_view file(std::string_view path) {
  const auto all = files();
  const auto found =
      std::find_if(all.begin(), all.end(), [&](const EmbeddedFile& f) { return f.path == path; });
  if (found == all.end()) throw std::logic_error("data file not embedded: " + std::string(path));
  return found->bytes;
}

}  // namespace matc::embedded_data
