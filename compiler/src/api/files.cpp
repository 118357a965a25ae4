#include "matc/api/files.h"

#include <filesystem>

#include "base/exclusive_file.h"
#include "pipeline/atomic_file.h"

namespace matc::api {

WriteOutcome write_file(std::string_view path, std::string_view bytes) {
  return write_file_atomically(std::filesystem::path(path), bytes) == matc::WriteOutcome::written
             ? WriteOutcome::written
             : WriteOutcome::unchanged;
}

std::string path_identity(std::string_view path) {
  return matc::path_identity(std::filesystem::path(path));
}

void remove_temporaries_in_flight() {
  matc::remove_temporaries_in_flight();
}

}  // namespace matc::api
