#include "base/content_hash.h"

#include <cstdint>

#include <fmt/format.h>
#include <xxhash.h>

#include "matc/version.h"

namespace matc {

ContentHash::ContentHash() {
  add(kVersion);
}

ContentHash& ContentHash::add(std::string_view part) {
  const std::string length = fmt::format("{}:", part.size());
  bytes_.insert(bytes_.end(), length.begin(), length.end());
  bytes_.insert(bytes_.end(), part.begin(), part.end());
  return *this;
}

std::string ContentHash::hex() const {
  return hash_of_bytes({bytes_.data(), bytes_.size()});
}

std::string hash_of_bytes(std::string_view bytes) {
  return fmt::format("{:016x}",
                     static_cast<std::uint64_t>(XXH3_64bits(bytes.data(), bytes.size())));
}

}  // namespace matc
