// The content hash every output carries, so that files from different inputs or matc versions are
// told apart (XXH3, 64 bits, as 16 hex digits).
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace matc {

class ContentHash {
 public:
  ContentHash();  // starts with the matc version, so a new version changes every hash
  // Adds a length-prefixed part, so ("ab", "c") and ("a", "bc") hash differently.
  ContentHash& add(std::string_view part);
  std::string hex() const;

 private:
  std::vector<char> bytes_;
};

// The hash of bytes as they are (a file's content).
std::string hash_of_bytes(std::string_view bytes);

}  // namespace matc
