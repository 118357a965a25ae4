#include "emit/manifest_writer.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "base/content_hash.h"
#include "base/json_format.h"
#include "base/pending_file.h"

namespace matc {
namespace {

nlohmann::ordered_json files_json(const std::vector<OutputFile>& files) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const OutputFile& file : files)
    list.push_back({{"file", file.name}, {"hash", hash_of_bytes(file.bytes)}});
  return list;
}

nlohmann::ordered_json manifest_head(const Build& build, const std::vector<OutputFile>& shared) {
  nlohmann::ordered_json manifest = build.description();
  manifest["shared_files"] = files_json(shared);
  manifest["materials"] = nlohmann::ordered_json::array();  // last: entries are streamed into it
  return manifest;
}

// The text between entries, and after the last: format_json's layout of the "materials" list.
std::string_view entry_separator(bool first) {
  return first ? "\n    " : ",\n    ";
}

std::string_view tail(std::size_t entry_count) {
  return entry_count == 0 ? "]\n}\n" : "\n  ]\n}\n";
}

}  // namespace

ManifestWriter::ManifestWriter(std::filesystem::path spool_directory)
    : spool_directory_(std::move(spool_directory)) {}

nlohmann::ordered_json ManifestWriter::entry(const MaterialOutputs& material) {
  return {{"name", material.name},
          {"source", material.source_path},
          {"inputs_hash", material.inputs_hash},
          {"files", files_json(material.files)}};
}

std::string ManifestWriter::format_entry(const MaterialOutputs& material) {
  return format_json_nested(entry(material), 2);  // an element of "materials", a top-level member
}

void ManifestWriter::append(std::string_view formatted_entry) {
  const std::string_view separator = entry_separator(count_ == 0);
  if (spool_directory_.empty()) {
    in_memory_.append(separator).append(formatted_entry);
    ++count_;
    return;
  }
  if (!spool_) {
    // Created on the first entry with no name (or exclusively, and unlinked at once).
    std::filesystem::create_directories(spool_directory_);
    PendingFile file = PendingFile::create(spool_directory_, "matc_manifest.entries");
    const int descriptor = ::dup(file.descriptor());
    if (descriptor >= 0) spool_.reset(::fdopen(descriptor, "w+b"));
    const int error = errno;
    if (!spool_ && descriptor >= 0) ::close(descriptor);
    file.discard();
    if (!spool_) {
      throw std::runtime_error(fmt::format("cannot open the manifest's entries in '{}': {}",
                                           spool_directory_.string(), std::strerror(error)));
    }
  }
  if (std::fwrite(separator.data(), 1, separator.size(), spool_.get()) != separator.size() ||
      std::fwrite(formatted_entry.data(), 1, formatted_entry.size(), spool_.get()) !=
          formatted_entry.size()) {
    throw std::runtime_error(fmt::format("cannot write the manifest's entries in '{}': {}",
                                         spool_directory_.string(), std::strerror(errno)));
  }
  ++count_;
}

void ManifestWriter::write(std::ostream& out, const Build& build,
                           const std::vector<OutputFile>& shared) {
  // "materials" is the last member: the rest is formatted as a whole, and the list opened where
  // format_json writes an empty one.
  std::string head = format_json(manifest_head(build, shared));
  const std::string empty_list = "[]\n}\n";
  if (!head.ends_with("\"materials\": " + empty_list))
    throw std::logic_error("manifest: materials is not last");
  head.resize(head.size() - empty_list.size());
  out << head << "[";
  if (spool_) {
    std::rewind(spool_.get());
    std::string block(1 << 16, '\0');
    while (const std::size_t read = std::fread(block.data(), 1, block.size(), spool_.get()))
      out.write(block.data(), static_cast<std::streamsize>(read));
    if (std::ferror(spool_.get()))
      throw std::runtime_error(fmt::format("cannot read back the manifest's entries in '{}'",
                                           spool_directory_.string()));
  } else {
    out << in_memory_;
  }
  out << tail(count_);
}

std::string ManifestWriter::text(const Build& build, const std::vector<OutputFile>& shared) {
  std::ostringstream out;
  write(out, build, shared);
  return out.str();
}

nlohmann::ordered_json manifest_json(const Build& build, const std::vector<OutputFile>& shared,
                                     std::span<const MaterialOutputs> materials) {
  nlohmann::ordered_json manifest = manifest_head(build, shared);
  for (const MaterialOutputs& material : materials)
    manifest["materials"].push_back(ManifestWriter::entry(material));
  return manifest;
}

}  // namespace matc
