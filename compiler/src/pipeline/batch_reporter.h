// What the three batches (compile, bake, import) share while they report: their events called
// one at a time (an empty callback or empty diagnostics skipped), the name their output goes by
// in messages, and the depfile written last.
#pragma once

#include <filesystem>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "pipeline/batch.h"
#include "pipeline/output_sink.h"

namespace matc {

class BatchReporter {
 public:
  explicit BatchReporter(const BatchEvents& events) : events_(events) {}
  void diagnostics(const Diagnostics& diagnostics);
  void progress(const BatchProgress& progress);
  void error(const std::string& where, const std::string& message);

 private:
  const BatchEvents& events_;
  std::mutex mutex_;
};

// The output's directory, or "output" for one held in memory: what targets and errors name.
std::filesystem::path output_name(const OutputSink& output);

// Writes the batch's depfile: `targets` depend on `dependencies`, then on `extra`. A failure is
// reported as the depfile's error; returns whether it was written.
bool write_batch_depfile(const std::filesystem::path& path,
                         const std::vector<std::filesystem::path>& targets,
                         std::vector<std::filesystem::path> dependencies,
                         std::span<const std::filesystem::path> extra, BatchReporter& reporter);

}  // namespace matc
