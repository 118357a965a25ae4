#include "matc/api/batch.h"

#include <set>
#include <stdexcept>

#include "checked_options.h"
#include "matc/emit/build.h"
#include "matc/pipeline/compile_batch.h"
#include "matc/pipeline/output_sink.h"
#include "public_diagnostics.h"

namespace matc::api {
namespace {

std::set<OutputKind> output_kinds(const std::vector<std::string>& names) {
  if (names.empty()) return all_output_kinds();
  std::set<OutputKind> kinds;
  for (const std::string& name : names)
    kinds.insert(checked_option_value<OutputKind>("emit", name));
  return kinds;
}

}  // namespace

BatchResult compile_batch(std::span<const BatchSource> sources, const BatchOptions& options,
                          const BatchEvents& events, std::stop_token cancel) {
  if (options.output_directory.empty())
    throw std::invalid_argument("output_directory: empty; the folder the files go to");
  BuildOptions build_options;
  build_options.emit = output_kinds(options.emit);
  build_options.basis = basis_of(options.compile);
  build_options.color = color_options_of(options.compile);
  const Build build(build_options);

  std::vector<MaterialSource> inputs;
  inputs.reserve(sources.size());
  for (const BatchSource& source : sources)
    inputs.push_back({source.path, source.text});
  CompileBatchOptions batch;
  batch.jobs = options.jobs;
  batch.keep_going = options.keep_going;
  batch.depfile = options.depfile;
  batch.cancel = std::move(cancel);
  matc::BatchEvents library_events;
  if (events.diagnostics) {
    library_events.diagnostics = [&](const Diagnostics& diagnostics) {
      events.diagnostics(public_diagnostics(diagnostics));
    };
  }
  if (events.progress) {
    library_events.progress = [&](const matc::BatchProgress& progress) {
      events.progress({progress.done, progress.total, std::string(progress.name)});
    };
  }
  library_events.error = events.error;
  DirectoryOutput output(options.output_directory);
  const CompileBatchResult result =
      matc::compile_batch(build, inputs, output, batch, library_events);
  return {result.counts.done,   result.counts.written,       result.counts.unchanged,
          result.counts.failed, result.counts.not_attempted, result.cancelled};
}

}  // namespace matc::api
