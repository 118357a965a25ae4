#include "matc/pipeline/output_sink.h"

#include <sstream>

namespace matc {

WriteOutcome DirectoryOutput::write(const std::string& name, std::string_view bytes) {
  std::filesystem::create_directories(directory_);
  return write_file_atomically(directory_ / name, bytes);
}

WriteOutcome DirectoryOutput::write(const std::string& name,
                                    const std::function<void(std::ostream&)>& produce) {
  std::filesystem::create_directories(directory_);
  return write_file_atomically(directory_ / name, produce);
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
