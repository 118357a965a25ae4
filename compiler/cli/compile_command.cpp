#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <stdexcept>

#include <fmt/core.h>

#include "atomic_file.h"
#include "commands.h"
#include "matc/compile.h"
#include "matc/json_format.h"
#include "matc/material/parse.h"
#include "print_diagnostics.h"

namespace matc::cli {
namespace {

namespace fs = std::filesystem;

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Canonical form of an existing path, for "would this output overwrite an input?" checks.
std::string identity(const fs::path& path) {
  std::error_code error;
  const fs::path canonical = fs::weakly_canonical(path, error);
  return error ? path.lexically_normal().string() : canonical.string();
}

struct BatchSummary {
  std::size_t compiled = 0;
  std::size_t written = 0;
  std::size_t unchanged = 0;
  std::size_t failed = 0;
};

}  // namespace

int run_compile(const CompileOptions& options) {
  const runtime::BasisView basis = runtime::paper_basis();
  const fs::path output_directory(options.output_directory);
  std::map<std::string, std::string> inputs_by_identity;
  for (const std::string& file : options.files)
    inputs_by_identity[identity(file)] = file;

  // Output names must be unique even on case-insensitive file systems.
  std::map<std::string, const Material*> names_in_use;
  std::vector<Material> materials;
  materials.reserve(options.files.size());
  BatchSummary summary;

  for (const std::string& file : options.files) {
    ParseResult parsed = read_material_file(file);
    Diagnostics diagnostics = std::move(parsed.diagnostics);
    if (parsed.material) {
      const Material& material = materials.emplace_back(std::move(*parsed.material));
      const fs::path output = output_directory / (material.name + ".json");
      if (const auto clash = names_in_use.find(lowercase(material.name));
          clash != names_in_use.end()) {
        diagnostics.error(material.name_location, "name",
                          fmt::format("'{}' is already used by {} ({}:{})", material.name,
                                      clash->second->source_path, clash->second->name_location.line,
                                      clash->second->name_location.column),
                          "names unique within a build, ignoring case (they name output files)");
      } else if (const auto input = inputs_by_identity.find(identity(output));
                 input != inputs_by_identity.end()) {
        diagnostics.error(
            material.name_location, "name",
            fmt::format("output '{}' would overwrite the input {}", output.string(), input->second),
            "an output directory (-o) that holds no input file");
      } else {
        names_in_use.emplace(lowercase(material.name), &material);
        try {
          const CompiledMaterial compiled = compile_material(material, basis);
          const std::string bytes = format_json(compiled_material_json(compiled, basis));
          fs::create_directories(output_directory);
          const WriteOutcome outcome = write_file_atomically(output, bytes);
          ++summary.compiled;
          ++(outcome == WriteOutcome::written ? summary.written : summary.unchanged);
        } catch (const std::exception& error) {
          diagnostics.error({output.string(), 0, 0}, "", error.what(),
                            "a writable output directory (-o)");
        }
      }
    }
    print_diagnostics(diagnostics);
    if (diagnostics.has_errors()) {
      ++summary.failed;
      if (!options.keep_going) break;
    }
  }

  if (!options.lut_format.empty() && (summary.failed == 0 || options.keep_going)) {
    const LutFormat format = *lut_format_from_name(options.lut_format);
    const fs::path path = output_directory / ("matc_lut" + std::string(lut_file_extension(format)));
    try {
      fs::create_directories(output_directory);
      const LutWriteCounts counts = write_lut_files(path, bake_lut(basis, options.lut.bake), format,
                                                    precision_of(options.lut));
      summary.written += counts.written;
      summary.unchanged += counts.unchanged;
    } catch (const std::exception& error) {
      fmt::print(stderr, "{}: error: {}\n", path.string(), error.what());
      ++summary.failed;
    }
  }

  if (!options.quiet) {
    const std::size_t attempted = summary.compiled + summary.failed;
    const std::size_t skipped =
        options.files.size() > attempted ? options.files.size() - attempted : 0;
    fmt::print(stderr, "matc: {} compiled ({} files written, {} unchanged), {} failed{}\n",
               summary.compiled, summary.written, summary.unchanged, summary.failed,
               skipped > 0 ? fmt::format(", {} not attempted (use --keep-going)", skipped) : "");
  }
  return summary.failed > 0 ? kExitInputError : kExitSuccess;
}

}  // namespace matc::cli
