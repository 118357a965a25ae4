// A batch, as `matc -o DIR FILES...` runs it: material files and texts held in memory compiled on
// several threads into one output directory, with the shared files, the manifest and a depfile;
// unchanged files keep their timestamps, and a material's files land all or none (docs/api.md).
// Native builds only (the WebAssembly library writes no files).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <stop_token>
#include <string>
#include <vector>

#include "matc/api/compiled_material.h"
#include "matc/api/diagnostics.h"

namespace matc::api {

struct BatchSource {
  // The file; for a text in memory, the name its diagnostics give it (its extension says which
  // kind it is, and relative spectral files resolve against its folder).
  std::string path;
  std::optional<std::string> text;
  static BatchSource file(std::string path) { return {std::move(path), std::nullopt}; }
  static BatchSource in_memory(std::string path, std::string text) {
    return {std::move(path), std::move(text)};
  }
};

struct BatchOptions {
  std::string output_directory;
  CompileOptions compile;
  // The outputs by --emit's names ("glsl", "hlsl", "wgsl", "spirv", "header", "json", "lut",
  // "coefficient-table", "ltc"); empty: all. A name outside them throws std::invalid_argument.
  std::vector<std::string> emit;
  std::string depfile;      // Make-syntax dependencies of every output; empty: none
  unsigned jobs = 0;        // materials compiled at once; 0: one per hardware thread
  bool keep_going = false;  // compile the others after one fails
};

struct BatchProgress {
  std::size_t done = 0;
  std::size_t total = 0;
  std::string name;  // the material just finished (empty when it failed before it had a name)
};

// Every callback may be empty; the batch calls one at a time, from any of its threads.
struct BatchEvents {
  std::function<void(const std::vector<Diagnostic>&)> diagnostics;  // each input's, in order
  std::function<void(const BatchProgress&)> progress;
  // A problem of the batch's own (its output directory, manifest or depfile), as the CLI prints
  // "WHERE: error: MESSAGE".
  std::function<void(const std::string& where, const std::string& message)> error;
};

struct BatchResult {
  std::size_t compiled = 0;
  std::size_t written = 0;    // files written
  std::size_t unchanged = 0;  // files whose bytes were already there
  std::size_t failed = 0;
  std::size_t not_attempted = 0;  // after a failure without keep_going, or a cancellation
  bool cancelled = false;
};

BatchResult compile_batch(std::span<const BatchSource> sources, const BatchOptions& options,
                          const BatchEvents& events = {}, std::stop_token cancel = {});

}  // namespace matc::api
