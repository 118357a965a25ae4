// `matc validate FILES...`: compile each material (material files and MaterialX documents) in
// memory (nothing is written) and prove its shaders on a Vulkan device.
#include <fmt/core.h>

#include "commands.h"
#include "device_validation_report.h"
#include "lut_options.h"
#include "matc/matc.h"
#include "name_options.h"
#include "print_diagnostics.h"

namespace matc::cli {
namespace {

struct ValidateOptions {
  std::vector<std::string> files;
  LutCliOptions lut;
  bool embed_lut = false;
  std::size_t embed_lut_size = 32;
  api::DeviceOptions device;
  api::CompileOptions color;  // its colour space and gamut mapping (the basis is lut's)
};

int run_validate(const ValidateOptions& options) {
  api::BuildOptions build_options =
      table_build_options(options.lut, options.embed_lut, options.embed_lut_size);
  build_options.compile.color_space = options.color.color_space;
  build_options.compile.gamut_mapping = options.color.gamut_mapping;
  const api::Build build(build_options);
  const std::unique_ptr<api::DeviceValidation> validation =
      open_device_validation(build, options.device);
  if (!validation) return kExitNoDevice;

  std::size_t invalid_files = 0;
  std::size_t validated = 0;
  std::size_t failed = 0;
  std::vector<std::string> failed_checks;
  validate_shared_files_and_report(*validation, &failed_checks);
  for (const std::string& file : options.files) {
    std::vector<api::Material> materials;
    try {
      materials = api::load_materials(file);
    } catch (const api::MaterialError& error) {
      print_diagnostics(error.diagnostics());
    }
    if (materials.empty()) {
      ++invalid_files;
      continue;
    }
    print_diagnostics(materials.front().diagnostics());  // the input's, which every one holds
    for (const api::Material& material : materials) {
      const api::CompiledMaterial compiled = build.compile(material);
      print_diagnostics(compiled.diagnostics(), material.diagnostics().size());  // the fit's
      ++validated;
      if (!validate_and_report(*validation, compiled)) ++failed;
    }
  }
  fmt::print("matc validate: {} of {} materials passed on both front ends{}\n", validated - failed,
             validated, invalid_files > 0 ? fmt::format(", {} files invalid", invalid_files) : "");
  for (const std::string& subject : failed_checks)
    fmt::print("matc validate: {} FAILED\n", subject);
  if (failed > 0 || !failed_checks.empty()) return kExitValidationFailed;
  return invalid_files > 0 ? kExitInputError : kExitSuccess;
}

}  // namespace

Command register_validate(CLI::App& app) {
  auto options = std::make_shared<ValidateOptions>();
  CLI::App* command = app.add_subcommand(
      "validate",
      "Run materials' generated shaders (GLSL and HLSL paths) on a Vulkan device and compare "
      "them with the CPU runtime; writes nothing");
  command
      ->add_option("files", options->files,
                   "Material files (.json) and MaterialX documents (.mtlx)")
      ->required();
  command->add_flag("--embed-lut", options->embed_lut,
                    "Also check the embedded-table path (lavapipe compiles tables "
                    "above 8x8 slowly: docs/validation.md)");
  command->add_option("--embed-lut-size", options->embed_lut_size, "Width and height of that table")
      ->capture_default_str()
      ->check(CLI::Range(api::kMinLutSize, api::kMaxEmbeddedLutSize));
  add_lut_options(*command, options->lut, "lut-", true);
  add_coefficient_table_option(*command, options->lut);
  add_device_options(*command, options->device);
  add_color_name_options(*command, options->color);

  return {command, [options] { return run_validate(*options); }, true};
}

}  // namespace matc::cli
