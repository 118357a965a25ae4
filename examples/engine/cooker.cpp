// An asset cooker: what a game's content pipeline does with libmatc's batch compile
// (matc/api/batch.h, the public API) instead of running the matc program. It cooks the material
// files named on its command line, plus one material its own code generates in memory, into one
// output directory: the same files, manifest and depfile `matc -o DIR --depfile DIR/cook.d
// FILES...` writes, with progress and cancellation in the cooker's hands.
//   cooker OUTPUT_DIR MATERIAL.json...
#include <cstdio>
#include <string>
#include <vector>

// BEGIN cooker-example
#include <stop_token>

#include "matc/api/batch.h"

namespace {

int cook(const std::string& output_directory, const std::vector<std::string>& files) {
  std::vector<matc::api::BatchSource> sources;
  for (const std::string& file : files)
    sources.push_back(matc::api::BatchSource::file(file));
  // A material the cooker makes itself (from a database, an editor): its text, a name for
  // diagnostics.
  sources.push_back(matc::api::BatchSource::in_memory(
      "generated/brushed_brass.json",
      R"({"name": "brushed_brass", "ior": {"n": [0.44, 0.53, 1.10], "k": [3.70, 2.90, 2.10]}})"));

  matc::api::BatchOptions options;  // what `matc` writes by default (every output, default basis)
  options.output_directory = output_directory;
  options.depfile = output_directory + "/cook.d";
  matc::api::BatchEvents events;
  events.diagnostics = [](const std::vector<matc::api::Diagnostic>& diagnostics) {
    for (const matc::api::Diagnostic& diagnostic : diagnostics)
      std::fprintf(stderr, "%s\n", diagnostic.text.c_str());
  };
  events.progress = [](const matc::api::BatchProgress& progress) {
    std::printf("cooked %zu/%zu %s\n", progress.done, progress.total, progress.name.c_str());
  };
  events.error = [](const std::string& where, const std::string& message) {
    std::fprintf(stderr, "%s: error: %s\n", where.c_str(), message.c_str());
  };
  std::stop_source cancel;  // an editor's Cancel button would call cancel.request_stop()
  const matc::api::BatchResult result =
      matc::api::compile_batch(sources, options, events, cancel.get_token());
  std::printf("%zu cooked (%zu files written, %zu unchanged), %zu failed%s\n", result.compiled,
              result.written, result.unchanged, result.failed,
              result.cancelled ? ", cancelled" : "");
  return result.failed > 0 || result.cancelled ? 1 : 0;
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
