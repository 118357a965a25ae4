#include "pipeline/output_sink.h"

#include <sstream>

namespace matc {

// Created on the first write, once: a batch writes thousands of files into it.
void DirectoryOutput::create_directory_once() {
  std::call_once(created_, [this] { std::filesystem::create_directories(directory_); });
}

WriteOutcome DirectoryOutput::write(const std::string& name, std::string_view bytes) {
  create_directory_once();
  return write_file_atomically(directory_ / name, bytes);
}

WriteOutcome DirectoryOutput::write(const std::string& name,
                                    const std::function<void(std::ostream&)>& produce) {
  create_directory_once();
  return write_file_atomically(directory_ / name, produce);
}

// One file at a time: all or none for a sink whose writes cannot fail midway (MemoryOutput);
// DirectoryOutput overrides it.
std::vector<WriteOutcome> OutputSink::write_all(std::span<const OutputFile> files) {
  std::vector<WriteOutcome> outcomes;
  for (const OutputFile& file : files)
    outcomes.push_back(write(file.name, file.bytes));
  return outcomes;
}

std::vector<WriteOutcome> DirectoryOutput::write_all(std::span<const OutputFile> files) {
  create_directory_once();
  return write_files_atomically(directory_, files);
}

WriteOutcome MemoryOutput::write(const std::string& name, std::string_view bytes) {
  const std::lock_guard lock(mutex_);
  auto [file, inserted] = files_.try_emplace(name);
  if (!inserted && file->second == bytes) return WriteOutcome::unchanged;
  file->second.assign(bytes);
  return WriteOutcome::written;
}

WriteOutcome MemoryOutput::write(const std::string& name,
                                 const std::function<void(std::ostream&)>& produce) {
  std::ostringstream out;
  produce(out);
  return write(name, out.view());
}

}  // namespace matc
