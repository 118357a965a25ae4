#include "matc/api/batch.h"

#include <optional>
#include <stdexcept>

#include "batch_events.h"
#include "checked_options.h"
#include "compiled_evaluation.h"
#include "emit/build.h"
#include "pipeline/compile_batch.h"
#include "pipeline/import_batch.h"
#include "pipeline/output_sink.h"

namespace matc::api {
namespace {

std::vector<MaterialSource> material_sources(std::span<const BatchSource> sources) {
  std::vector<MaterialSource> inputs;
  inputs.reserve(sources.size());
  for (const BatchSource& source : sources)
    inputs.push_back({source.path, source.text});
  return inputs;
}

}  // namespace

BatchResult compile_batch(std::span<const BatchSource> sources, const BatchOptions& options,
                          const BatchEvents& events, std::stop_token cancel) {
  BuildOptions build;
  build.compile = options.compile;
  build.emit = options.emit;
  BatchOptions rest = options;
  rest.compile = {};
  rest.emit.clear();
  return compile_batch(Build(build), sources, rest, events, std::move(cancel));
}

BatchResult compile_batch(const Build& build, std::span<const BatchSource> sources,
                          const BatchOptions& options, const BatchEvents& events,
                          std::stop_token cancel) {
  const CompileOptions& compile = options.compile;
  if (!compile.basis.empty() || !compile.color_space.empty() || !compile.gamut_mapping.empty() ||
      !options.emit.empty()) {
    throw std::invalid_argument(
        "compile, emit: set with a Build, whose options a batch with it uses; leave them empty");
  }
  if (options.in_memory && !options.output_directory.empty()) {
    throw std::invalid_argument(
        "output_directory: set with in_memory; a batch writes to one or the other");
  }
  if (!options.in_memory && options.output_directory.empty())
    throw std::invalid_argument("output_directory: empty; the folder the files go to");

  const std::vector<MaterialSource> inputs = material_sources(sources);
  CompileBatchOptions batch;
  batch.jobs = options.jobs;
  batch.keep_going = options.keep_going;
  batch.no_shared = options.no_shared;
  batch.shared_only = options.shared_only;
  batch.depfile = options.depfile;
  for (const std::string& dependency : options.extra_dependencies)
    batch.extra_dependencies.emplace_back(dependency);
  batch.cancel = std::move(cancel);
  if (options.check_material) {
    // Each material with the basis it was compiled against (its own in a per-material build).
    batch.check_material = [&options, &build](const matc::CompiledMaterial& compiled) {
      return options.check_material(
          public_compiled(std::make_shared<const matc::CompiledMaterial>(compiled),
                          build.value().basis_choice(), {}));
    };
  }
  std::optional<MemoryOutput> memory;
  std::optional<DirectoryOutput> directory;
  OutputSink& output = options.in_memory
                           ? static_cast<OutputSink&>(memory.emplace())
                           : static_cast<OutputSink&>(directory.emplace(options.output_directory));
  const CompileBatchResult result =
      matc::compile_batch(build.value(), inputs, output, batch, library_events(events));
  BatchResult out = public_result(result.counts, result.cancelled);
  out.failed_checks = result.failed_checks;
  if (memory) out.files = memory->files();
  return out;
}

BatchResult import_batch(std::span<const BatchSource> documents, const ImportOptions& options,
                         const BatchEvents& events) {
  if (options.output_directory.empty())
    throw std::invalid_argument("output_directory: empty; the folder the files go to");
  const std::vector<MaterialSource> inputs = material_sources(documents);
  DirectoryOutput output(options.output_directory);
  return public_result(
      matc::import_batch(inputs, output, {options.keep_going}, library_events(events)));
}

}  // namespace matc::api
