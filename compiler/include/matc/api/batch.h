// A batch, as `matc -o DIR FILES...` runs it: material files and texts held in memory compiled on
// several threads into one output directory, with the shared files, the manifest and a depfile;
// unchanged files keep their timestamps, and a material's files land all or none (docs/api.md).
// Or the same files kept in memory. Native builds only (the WebAssembly library writes no files).
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <stop_token>
#include <string>
#include <vector>

#include "matc/api/build.h"
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
  std::string output_directory;  // where the files go; required unless in_memory
  bool in_memory = false;        // keep the files in BatchResult::files instead
  // The build's options, for the call without a Build (a Build's own options otherwise: these
  // must then be left empty). The outputs by --emit's names ("glsl", "hlsl", "wgsl", "spirv",
  // "header", "json", "lut", "coefficient-table", "ltc"); empty: all. A name outside them throws
  // std::invalid_argument.
  CompileOptions compile;
  std::vector<std::string> emit;
  std::string depfile;  // Make-syntax dependencies of every output (a directory's); empty: none
  // Listed in the depfile after the inputs and spectral files (the CLI lists the matc program).
  std::vector<std::string> extra_dependencies;
  unsigned jobs = 0;         // materials compiled at once; 0: one per hardware thread
  bool keep_going = false;   // compile the others after one fails
  bool no_shared = false;    // each material's own files only: no shared files, no manifest
  bool shared_only = false;  // the shared files only (give no source)
  // Run on each compiled material before its files are written (`matc --validate` runs its
  // shaders on a device there, matc/api/validation.h); false: none of its files are written and
  // it fails. Called one at a time.
  std::function<bool(const CompiledMaterial&)> check_material;
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
  // "WHERE: error: MESSAGE"; both escaped as diagnostics are (no control bytes).
  std::function<void(const std::string& where, const std::string& message)> error;
};

struct BatchResult {
  std::size_t compiled = 0;
  std::size_t written = 0;    // files written
  std::size_t unchanged = 0;  // files whose bytes were already there
  std::size_t failed = 0;
  std::size_t not_attempted = 0;  // after a failure without keep_going, or a cancellation
  bool cancelled = false;
  std::size_t failed_checks = 0;             // materials check_material refused
  std::map<std::string, std::string> files;  // name to bytes, for a batch in memory
};

// Throws std::invalid_argument for options out of range or that contradict each other
// (shared_only with sources, a depfile or no output directory without in_memory).
BatchResult compile_batch(std::span<const BatchSource> sources, const BatchOptions& options,
                          const BatchEvents& events = {}, std::stop_token cancel = {});
// The same with `build`'s outputs (its tables baked once for many batches).
BatchResult compile_batch(const Build& build, std::span<const BatchSource> sources,
                          const BatchOptions& options, const BatchEvents& events = {},
                          std::stop_token cancel = {});

// `matc import -o DIR DOCUMENTS...`: each metallic material of MaterialX documents and glTF assets
// (sources, on disk or in memory) written as its material file <name>.json into
// `output_directory`. Every document is imported and every name checked before anything is
// written: without keep_going a failing batch writes nothing. `compiled` counts the materials
// written, `failed` the documents that failed.
struct ImportOptions {
  std::string output_directory;
  bool keep_going = false;  // write the other documents' materials when one fails
};
BatchResult import_batch(std::span<const BatchSource> documents, const ImportOptions& options,
                         const BatchEvents& events = {});

}  // namespace matc::api
