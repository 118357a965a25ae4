#include "manifest_spool.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "matc/emit/build.h"

namespace matc::cli {

void ManifestSpool::append(std::string_view formatted_entry) {
  if (!file_) {
    // Created on the first entry and unlinked at once: nothing is left behind, even by a
    // killed matc.
    std::filesystem::create_directories(directory_);
    const std::filesystem::path path =
        directory_ / fmt::format(".matc_manifest.entries.tmp{}", ::getpid());
    file_.reset(std::fopen(path.c_str(), "w+b"));
    if (!file_) {
      throw std::runtime_error(
          fmt::format("cannot create '{}': {}", path.string(), std::strerror(errno)));
    }
    std::filesystem::remove(path);
  }
  const std::string_view separator = Build::manifest_entry_separator(count_ == 0);
  if (std::fwrite(separator.data(), 1, separator.size(), file_.get()) != separator.size() ||
      std::fwrite(formatted_entry.data(), 1, formatted_entry.size(), file_.get()) !=
          formatted_entry.size()) {
    throw std::runtime_error(fmt::format("cannot write the manifest's entries in '{}': {}",
                                         directory_.string(), std::strerror(errno)));
  }
  ++count_;
}

void ManifestSpool::copy_to(std::ostream& out) {
  if (!file_) return;
  std::rewind(file_.get());
  std::string block(1 << 16, '\0');
  while (const std::size_t read = std::fread(block.data(), 1, block.size(), file_.get()))
    out.write(block.data(), static_cast<std::streamsize>(read));
  if (std::ferror(file_.get()))
    throw std::runtime_error(
        fmt::format("cannot read back the manifest's entries in '{}'", directory_.string()));
}

}  // namespace matc::cli
