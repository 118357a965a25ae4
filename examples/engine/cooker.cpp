// An asset cooker: what a game's content pipeline does with libmatc's batch compile
// (matc/pipeline/compile_batch.h) instead of running the matc program. It cooks the material files
// named on its command line, plus one material its own code generates in memory, into one output
// directory: the same files, manifest and depfile `matc -o DIR --depfile DIR/cook.d FILES...`
// writes, with progress and cancellation in the cooker's hands.
//   cooker OUTPUT_DIR MATERIAL.json...
#include <cstdio>
#include <string>
#include <vector>

// BEGIN cooker-example
#include "matc/emit/build.h"
#include "matc/pipeline/compile_batch.h"

namespace {

int cook(const std::string& output_directory, const std::vector<std::string>& files) {
  std::vector<matc::MaterialSource> sources;
  for (const std::string& file : files)
    sources.push_back(matc::MaterialSource::file(file));
  // A material the cooker makes itself (from a database, an editor): its text, a name for
  // diagnostics.
  sources.push_back(matc::MaterialSource::in_memory(
      "generated/brushed_brass.json",
      R"({"name": "brushed_brass", "ior": {"n": [0.44, 0.53, 1.10], "k": [3.70, 2.90, 2.10]}})"));

  const matc::Build build(matc::BuildOptions{});  // what `matc` writes by default
  matc::CompileBatchOptions options;
  options.depfile = output_directory + "/cook.d";
  std::stop_source cancel;  // an editor's Cancel button would call cancel.request_stop()
  options.cancel = cancel.get_token();
  matc::BatchEvents events;
  events.diagnostics = [](const matc::Diagnostics& diagnostics) {
    for (const matc::Diagnostic& diagnostic : diagnostics.items())
      std::fprintf(stderr, "%s\n", matc::format_diagnostic(diagnostic).c_str());
  };
  events.progress = [](const matc::BatchProgress& progress) {
    std::printf("cooked %zu/%zu %.*s\n", progress.done, progress.total,
                static_cast<int>(progress.name.size()), progress.name.data());
  };
  events.error = [](const std::string& where, const std::string& message) {
    std::fprintf(stderr, "%s: error: %s\n", where.c_str(), message.c_str());
  };
  matc::DirectoryOutput output(output_directory);
  const matc::CompileBatchResult result =
      matc::compile_batch(build, sources, output, options, events);
  std::printf("%zu cooked (%zu files written, %zu unchanged), %zu failed%s\n", result.counts.done,
              result.counts.written, result.counts.unchanged, result.counts.failed,
              result.cancelled ? ", cancelled" : "");
  return result.counts.failed > 0 || result.cancelled ? 1 : 0;
}

}  // namespace
// END cooker-example

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: cooker OUTPUT_DIR MATERIAL.json...\n");
    return 2;
  }
  return cook(argv[1], std::vector<std::string>(argv + 2, argv + argc));
}
