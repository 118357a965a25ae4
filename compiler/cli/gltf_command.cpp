// `matc gltf`: a glTF asset written back with each metal's compiled coefficients in the vendor
// extension MATC_materials_fresnel, every other byte carried through (docs/gltf.md).
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "matc/api/diagnostics.h"
#include "matc/api/files.h"
#include "matc/matc.h"
#include "name_options.h"
#include "option_help.h"
#include "print_diagnostics.h"

namespace matc::cli {
namespace {

namespace fs = std::filesystem;

struct GltfOptions {
  std::string input;
  std::string output;
  api::CompileOptions compile;
  bool quiet = false;
};

bool ends_with_any_case(const std::string& path, std::string_view extension) {
  if (path.size() < extension.size()) return false;
  for (std::size_t i = 0; i < extension.size(); ++i) {
    const char c = path[path.size() - extension.size() + i];
    if (static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c) != extension[i]) return false;
  }
  return true;
}

// Why the asset may not be written to `output`: into its own input, or a .gltf away from the
// files it names beside it (they would not resolve). Empty when it may.
std::string output_problem(const GltfOptions& options, const api::GltfAsset& asset) {
  const fs::path input(options.input);
  const fs::path output(options.output);
  const std::string written = api::path_identity(output.string());
  if (written == api::path_identity(input.string()))
    return fmt::format("output '{}' would overwrite its input", api::printable(options.output));
  for (const std::string& uri : asset.external_uris) {
    if (written == api::path_identity((input.parent_path() / uri).string()))
      return fmt::format("output '{}' would overwrite '{}', a file the asset names",
                         api::printable(options.output), api::echoed(uri, 128));
  }
  const auto folder = [](const fs::path& path) {
    return api::path_identity(
        (path.parent_path().empty() ? fs::path(".") : path.parent_path()).string());
  };
  if (!asset.external_uris.empty() && folder(output) != folder(input)) {
    return fmt::format(
        "output '{}' is not in the folder of '{}', whose asset names {} file(s) beside it "
        "('{}'...): they would not resolve from there",
        api::printable(options.output), api::printable(options.input), asset.external_uris.size(),
        api::echoed(asset.external_uris.front(), 128));
  }
  return {};
}

int run_gltf(const GltfOptions& options) {
  const bool binary = ends_with_any_case(options.input, ".glb");
  if (!binary && !ends_with_any_case(options.input, ".gltf")) {
    fmt::print(stderr,
               "matc gltf: error: '{}' names no glTF asset; an asset ending in .gltf or .glb\n",
               api::printable(options.input));
    return kExitUsageError;
  }
  if (!ends_with_any_case(options.output, binary ? ".glb" : ".gltf")) {
    fmt::print(stderr,
               "matc gltf: error: --output '{}': the asset is a {} and is written as one; an "
               "output ending in {}\n",
               api::printable(options.output), binary ? ".glb" : ".gltf",
               binary ? ".glb" : ".gltf");
    return kExitUsageError;
  }
  api::GltfAsset asset;
  try {
    asset = api::compile_gltf_file(options.input, options.compile);
  } catch (const api::MaterialError& error) {
    print_diagnostics(error.diagnostics());
    return kExitInputError;
  }
  // Every material carries the asset's notes; each compile adds its own after them.
  const std::size_t asset_notes = asset.materials.front().material().diagnostics().size();
  print_diagnostics(asset.materials.front().material().diagnostics());
  for (const api::CompiledMaterial& material : asset.materials)
    print_diagnostics(material.diagnostics(), asset_notes);
  if (const std::string problem = output_problem(options, asset); !problem.empty()) {
    fmt::print(stderr, "matc gltf: error: {}\n", problem);
    return kExitInputError;
  }
  try {
    const fs::path output(options.output);
    if (!output.parent_path().empty()) fs::create_directories(output.parent_path());
    api::write_file(output.string(), asset.bytes);
  } catch (const std::exception& error) {
    fmt::print(stderr, "matc gltf: error: cannot write '{}': {}\n", api::printable(options.output),
               api::printable(error.what()));
    return kExitInputError;
  }
  if (!options.quiet) {
    std::string names;
    for (const api::CompiledMaterial& material : asset.materials)
      names += (names.empty() ? "" : ", ") + material.name();
    fmt::print("matc gltf: {}: {} metal(s) with MATC_materials_fresnel ({}; basis {})\n",
               api::printable(options.output), asset.materials.size(), names,
               options.compile.basis);
  }
  return kExitSuccess;
}

}  // namespace

Command register_gltf(CLI::App& app) {
  auto options = std::make_shared<GltfOptions>();
  CLI::App* command = app.add_subcommand(
      "gltf",
      "Write a glTF asset back with each metal's compiled coefficients in the vendor extension "
      "MATC_materials_fresnel, every other byte as it was (docs/gltf.md)");
  command->add_option("asset", options->input, "The glTF asset (.gltf or .glb)")->required();
  command
      ->add_option("-o,--output", options->output,
                   "The asset written (.glb for a .glb, .gltf for a .gltf; a .gltf that names "
                   "files beside it goes into its own folder)")
      ->required();
  add_name_option(*command, "--basis", options->compile.basis, "basis", kBasisHelp);
  add_color_name_options(*command, options->compile);
  command->add_flag("-q,--quiet", options->quiet, "No summary line");
  return {command, [options] { return run_gltf(*options); }, true};
}

}  // namespace matc::cli
