#include "batch_reporter.h"

#include <exception>

#include "pipeline/depfile.h"

namespace matc {

void BatchReporter::diagnostics(const Diagnostics& diagnostics) {
  if (!events_.diagnostics || diagnostics.items().empty()) return;
  const std::lock_guard lock(mutex_);
  events_.diagnostics(diagnostics);
}

void BatchReporter::progress(const BatchProgress& progress) {
  if (!events_.progress) return;
  const std::lock_guard lock(mutex_);
  events_.progress(progress);
}

void BatchReporter::error(const std::string& where, const std::string& message) {
  if (!events_.error) return;
  const std::lock_guard lock(mutex_);
  events_.error(where, message);
}

std::filesystem::path output_name(const OutputSink& output) {
  const std::filesystem::path* directory = output.directory();
  return directory ? *directory : std::filesystem::path("output");
}

bool write_batch_depfile(const std::filesystem::path& path,
                         const std::vector<std::filesystem::path>& targets,
                         std::vector<std::filesystem::path> dependencies,
                         std::span<const std::filesystem::path> extra, BatchReporter& reporter) {
  dependencies.insert(dependencies.end(), extra.begin(), extra.end());
  try {
    write_depfile(path, targets, dependencies);
    return true;
  } catch (const std::exception& error) {
    reporter.error(path.string(), error.what());
    return false;
  }
}

}  // namespace matc
