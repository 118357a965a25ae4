#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include <fmt/core.h>

#include "atomic_file.h"
#include "commands.h"
#include "device_validation_report.h"
#include "matc/compile.h"
#include "matc/emit/build.h"
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

// Stems of the files every build writes once; a material of that name would overwrite them.
const std::set<std::string>& reserved_names() {
  static const std::set<std::string> names = {"matc_fresnel", "matc_lut", "matc_manifest"};
  return names;
}

// Every file a material of this name may write, whatever --emit says.
std::vector<fs::path> possible_outputs(const fs::path& directory, const std::string& name) {
  std::vector<fs::path> paths;
  for (const char* extension : {".json", ".glsl", ".hlsl", ".spv", ".h"})
    paths.push_back(directory / (name + extension));
  return paths;
}

BuildOptions build_options(const CompileOptions& options) {
  BuildOptions build;
  if (!options.emit.empty()) {
    build.emit.clear();
    for (const std::string& name : split_list(options.emit))
      build.emit.insert(*output_kind_from_name(name));
  }
  build.lut = options.lut.bake;
  build.lut_format = *lut_format_from_name(options.lut_format);
  build.lut_precision = precision_of(options.lut);
  build.embedded_lut_size = options.embed_lut ? options.embed_lut_size : 0;
  return build;
}

struct BatchSummary {
  std::size_t compiled = 0;
  std::size_t written = 0;
  std::size_t unchanged = 0;
  std::size_t failed = 0;
  std::size_t failed_on_device = 0;

  void count(WriteOutcome outcome) { ++(outcome == WriteOutcome::written ? written : unchanged); }
};

}  // namespace

std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    items.push_back(list.substr(start, comma - start));
    start = comma + 1;
  }
  return items;
}

int run_compile(const CompileOptions& options) {
  const Build build(build_options(options));
  std::unique_ptr<DeviceValidator> validator;
  if (options.validate) {
    validator = open_device_validator(build, options.device);
    if (!validator) return kExitNoDevice;
  }
  const runtime::BasisView basis = runtime::paper_basis();
  const fs::path output_directory(options.output_directory);
  std::map<std::string, std::string> inputs_by_identity;
  for (const std::string& file : options.files)
    inputs_by_identity[identity(file)] = file;

  // Output names must be unique even on case-insensitive file systems.
  std::map<std::string, const Material*> names_in_use;
  std::vector<Material> materials;
  materials.reserve(options.files.size());
  std::vector<MaterialOutputs> written_materials;
  BatchSummary summary;

  for (const std::string& file : options.files) {
    ParseResult parsed = read_material_file(file);
    Diagnostics diagnostics = std::move(parsed.diagnostics);
    if (parsed.material) {
      const Material& material = materials.emplace_back(std::move(*parsed.material));
      const std::vector<fs::path> outputs = possible_outputs(output_directory, material.name);
      const auto overwritten = std::find_if(outputs.begin(), outputs.end(), [&](const fs::path& p) {
        return inputs_by_identity.contains(identity(p));
      });
      if (reserved_names().contains(lowercase(material.name))) {
        diagnostics.error(material.name_location, "name",
                          fmt::format("'{}' names a file every build writes", material.name),
                          "a name other than matc_fresnel, matc_lut and matc_manifest "
                          "(ignoring case)");
      } else if (const auto clash = names_in_use.find(lowercase(material.name));
                 clash != names_in_use.end()) {
        diagnostics.error(material.name_location, "name",
                          fmt::format("'{}' is already used by {} ({}:{})", material.name,
                                      clash->second->source_path, clash->second->name_location.line,
                                      clash->second->name_location.column),
                          "names unique within a build, ignoring case (they name output files)");
      } else if (overwritten != outputs.end()) {
        diagnostics.error(
            material.name_location, "name",
            fmt::format("output '{}' would overwrite the input {}", overwritten->string(),
                        inputs_by_identity.at(identity(*overwritten))),
            "an output directory (-o) that holds no input file");
      } else {
        names_in_use.emplace(lowercase(material.name), &material);
        try {
          // Every byte is generated before the first file is written: a failure leaves no
          // partial set of outputs for this material.
          const CompiledMaterial compiled = compile_material(material, basis);
          MaterialOutputs outputs_of_material = build.material_outputs(compiled);
          if (validator && !validate_and_report(*validator, compiled)) {
            ++summary.failed_on_device;
            diagnostics.error({file, 0, 0}, "",
                              "its shaders differ from the CPU runtime on the Vulkan device "
                              "(lines above); nothing written for it");
          } else {
            fs::create_directories(output_directory);
            for (const OutputFile& output : outputs_of_material.files)
              summary.count(write_file_atomically(output_directory / output.name, output.bytes));
            ++summary.compiled;
            written_materials.push_back(std::move(outputs_of_material));
          }
        } catch (const std::exception& error) {
          diagnostics.error({file, 0, 0}, "", error.what(), "a writable output directory (-o)");
        }
      }
    }
    print_diagnostics(diagnostics);
    if (diagnostics.has_errors()) {
      ++summary.failed;
      if (!options.keep_going) break;
    }
  }

  if (summary.failed == 0 || options.keep_going) {
    try {
      fs::create_directories(output_directory);
      std::vector<OutputFile> shared = build.shared_outputs();
      for (const OutputFile& output : shared)
        summary.count(write_file_atomically(output_directory / output.name, output.bytes));
      if (build.options().emit.contains(OutputKind::json)) {
        summary.count(
            write_file_atomically(output_directory / manifest_file_name(),
                                  format_json(build.manifest(shared, written_materials))));
      }
    } catch (const std::exception& error) {
      fmt::print(stderr, "{}: error: {}\n", output_directory.string(), error.what());
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
  if (summary.failed_on_device > 0) return kExitValidationFailed;
  return summary.failed > 0 ? kExitInputError : kExitSuccess;
}

}  // namespace matc::cli
