// The batch compile: what `matc -o DIR FILES...` does, for any tool that links libmatc (an editor,
// an asset server, a game's cooker). Sources are read and checked in order (names unique within
// the batch and free of the shared files' names, no output overwriting an input), compiled on
// several threads, and retired in input order: each material's diagnostics are reported and its
// manifest entry appended as soon as every earlier one is done, so a batch of any size holds
// little per material. Every byte of a material is generated before its first file is written:
// a failure leaves no partial set of its files. The shared files, the manifest and the depfile
// are written last, and only when nothing failed (or keep_going).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <stop_token>
#include <string>
#include <vector>

#include "compile/compile.h"
#include "emit/build.h"
#include "pipeline/batch.h"
#include "pipeline/output_sink.h"

namespace matc {

// One input of a batch: a material file (.json) or a MaterialX document (.mtlx), on disk or held
// in memory.
struct MaterialSource {
  // The file; for a text in memory, the name its diagnostics give it (its extension says which
  // kind it is, and relative spectral files resolve against its folder).
  std::string path;
  std::optional<std::string> text;  // the contents, when held in memory (nothing read from disk)

  static MaterialSource file(std::string path) { return {std::move(path), std::nullopt}; }
  static MaterialSource in_memory(std::string path, std::string text) {
    return {std::move(path), std::move(text)};
  }
};

struct CompileBatchOptions {
  unsigned jobs = 0;         // materials compiled at once; 0: one per hardware thread
  bool keep_going = false;   // compile the others after one fails (an invalid input stops all)
  bool no_shared = false;    // only each material's own files: no shared files, no manifest
  bool shared_only = false;  // only the shared files (give no source)
  // Make-syntax dependencies of every output (DirectoryOutput only); empty: none.
  std::filesystem::path depfile;
  // Listed in the depfile after the inputs and spectral files (the matc binary, for the CLI).
  std::vector<std::filesystem::path> extra_dependencies;
  // Runs a compiled material's shaders (on a device, say) before its files are written; false:
  // none of its files are written and it fails. Called one at a time, never while a diagnostics
  // event runs.
  std::function<bool(const CompiledMaterial&)> check_material;
  std::stop_token cancel;  // once requested, no new material starts and nothing shared is written
};

struct CompileBatchResult {
  BatchCounts counts;
  std::size_t failed_checks = 0;  // materials check_material refused
  bool cancelled = false;
};

// Compiles `sources` with `build`'s options into `output`, reporting through `events`. Throws
// std::invalid_argument for options that contradict each other (shared_only with sources, a
// depfile for an output that is not a directory).
CompileBatchResult compile_batch(const Build& build, std::span<const MaterialSource> sources,
                                 OutputSink& output, const CompileBatchOptions& options = {},
                                 const BatchEvents& events = {});

}  // namespace matc
