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
  const std::size_t asset_notes = asset.notes.size();
  print_diagnostics(asset.notes);
  for (const api::CompiledMaterial& material : asset.materials)
    print_diagnostics(material.diagnostics(), asset_notes);
  api::GltfFilesCopied copied;
  try {
    copied = api::write_gltf(asset, options.input, options.output);
  } catch (const std::invalid_argument& problem) {
    fmt::print(stderr, "matc gltf: error: {}\n", problem.what());
    return kExitInputError;
  } catch (const std::exception& error) {
    fmt::print(stderr, "matc gltf: error: cannot write '{}': {}\n", api::printable(options.output),
               api::printable(error.what()));
    return kExitInputError;
  }
  if (!options.quiet) {
    std::string names;
    for (const api::CompiledMaterial& material : asset.materials)
      names += (names.empty() ? "" : ", ") + material.name();
    if (asset.materials.empty()) {
      fmt::print("matc gltf: {}: no metal, written unchanged\n", api::printable(options.output));
    } else {
      fmt::print("matc gltf: {}: {} metal(s) with MATC_materials_fresnel ({}; basis {})\n",
                 api::printable(options.output), asset.materials.size(), names,
                 options.compile.basis);
    }
    const std::size_t beside = copied.written.size() + copied.unchanged.size();
    if (beside > 0)
      fmt::print("matc gltf: {} file(s) the asset names copied beside it ({} unchanged)\n", beside,
                 copied.unchanged.size());
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
                   "The asset written (.glb for a .glb, .gltf for a .gltf; the files a .gltf "
                   "names beside it are copied beside the output when it is in another folder)")
      ->required();
  add_name_option(*command, "--basis", options->compile.basis, "build_basis", kBuildBasisHelp,
                  api::option_default("build_basis"));
  add_color_name_options(*command, options->compile);
  command->add_flag("-q,--quiet", options->quiet, "No summary line");
  return {command, [options] { return run_gltf(*options); }, true};
}

}  // namespace matc::cli
