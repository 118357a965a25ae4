// A build: the options of one `matc` run and everything it writes, made in memory (docs/api.md):
// the shared shader library and tables, each material's shader sources and files, byte for byte
// what `matc -o` writes with the same options. A batch (matc/api/batch.h) writes a build's files
// into a directory. Native builds only (SPIR-V, the tables' files).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "matc/api/compiled_material.h"
#include "matc/api/files.h"
#include "matc/api/tables.h"

namespace matc {
class Build;
}

namespace matc::api {

// By the CLI's option names and values; an empty name means the default.
struct BuildOptions {
  // --emit: "glsl", "hlsl", "wgsl", "spirv", "header", "json", "lut", "coefficient-table",
  // "ltc"; empty: all.
  std::vector<std::string> emit;
  std::size_t lut_size = kDefaultLutSize;        // --lut-size
  std::size_t lut_samples = kDefaultLutSamples;  // --lut-samples
  std::string lut_format;                        // --lut-format: ktx2 (default), dds, raw, header
  std::string lut_precision;                     // --lut-precision: f32 (default), f16
  std::string coefficient_table_precision;       // f16 (default), f32
  std::size_t embed_lut = 0;  // --embed-lut-size: 0 for none, else 2..kMaxEmbeddedLutSize
  CompileOptions compile;     // --basis, --color-space, --gamut-mapping
};
inline constexpr std::size_t kMaxEmbeddedLutSize = 64;

// Immutable and thread-safe; cheap to copy (shared). Tables are baked on first use.
class Build {
 public:
  // Throws std::invalid_argument naming an option out of range or outside its names.
  explicit Build(const BuildOptions& options = {});

  // The options with every default filled in and `emit` in matc's order.
  const BuildOptions& options() const { return options_; }

  // `material` compiled with this build's compile options.
  CompiledMaterial compile(const Material& material) const;
  // "glsl", "hlsl" or "wgsl" (std::invalid_argument otherwise). A material compiled with other
  // compile options than this build's throws std::invalid_argument.
  const std::string& library_source(std::string_view language) const;
  std::string material_source(std::string_view language, const CompiledMaterial& compiled) const;
  // The material's own files (<name>.glsl, .hlsl, .wgsl, .spv, .h, .json as emitted) and the
  // shared ones (the libraries, the tables and their descriptions), as `matc` writes them.
  std::vector<OutputFile> material_files(const CompiledMaterial& compiled) const;
  std::vector<OutputFile> shared_files() const;
  // The tables as this build's files store them: the preintegrated table's layer of `basis` (empty:
  // the first; a default build holds a layer per basis, "powers" then "f82", side by side in its
  // file; another basis throws std::invalid_argument), and the coefficient table.
  PreintegratedTable lut(std::string_view basis = {}) const;
  CoefficientTable coefficient_table() const;
  // The head of matc_manifest.json (version, inputs hash, options, the tables' files), as JSON.
  std::string description() const;

  // The library's own value, for the library's implementation.
  const matc::Build& value() const { return *build_; }

 private:
  BuildOptions options_;
  std::shared_ptr<const matc::Build> build_;
};

}  // namespace matc::api
