// matc: compiles material files into Fresnel coefficients, shaders, SPIR-V, headers and the LUT.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include "commands.h"
#include "file_list.h"
#include "matc/emit/build.h"
#include "matc/ltc/area_light_reference.h"
#include "matc/version.h"
#include "print_diagnostics.h"

int main(int argc, char** argv) {
  using namespace matc::cli;
  CLI::App app{"matc: compiles materials into an accurate, preintegrable Fresnel decomposition",
               "matc"};
  app.set_version_flag("--version", std::string("matc ") + matc::kVersion);
  app.footer(
      "Exit status: 0 success, 1 invalid input, 2 invalid command line, 3 internal error, "
      "4 shaders differ from the CPU runtime on the device, 5 no usable Vulkan device.");

  CompileOptions compile;
  app.add_option("files", compile.files,
                 "Material files (.json) and MaterialX documents (.mtlx) to compile");
  std::string files_from;
  app.add_option("--files-from", files_from,
                 "Also compile the files listed in FILE, one path per line (- for standard input): "
                 "for lists longer than a command line holds");
  app.add_option("-o,--output", compile.output_directory, "Output directory (created if missing)")
      ->capture_default_str();
  app.add_flag("-k,--keep-going", compile.keep_going,
               "Compile the remaining files after one fails (still exits 1)");
  app.add_flag("-q,--quiet", compile.quiet, "Do not print the progress and summary lines");
  app.add_option("-j,--jobs", compile.jobs,
                 "Materials compiled at once (default: one per hardware thread)")
      ->check(CLI::Range(1u, 1024u));
  app.add_option("--depfile", compile.depfile,
                 "Write the outputs' dependencies (inputs, spectral files, the matc binary) to "
                 "FILE in the Makefile syntax Ninja and CMake read");
  app.add_flag("--MD", compile.write_depfile, "The same, as DIR/matc.d (also spelled -MD)");
  app.add_option("--emit", compile.emit,
                 "Outputs to write, comma-separated (default: all): shader snippets, SPIR-V, "
                 "C headers, JSON manifests, the LUT, the coefficient table of textured metals, "
                 "the LTC table of area lights")
      ->check(CLI::Validator(
          [](std::string& list) -> std::string {
            for (const std::string& name : split_list(list)) {
              if (!matc::output_kind_from_name(name)) {
                return "'" + name + "' is not one of " +
                       CLI::detail::join(matc::output_kind_names(), ",");
              }
            }
            return {};
          },
          "LIST", "output kinds"));
  CLI::Option* no_shared_option = app.add_flag(
      "--no-shared", compile.no_shared,
      "Write only each material's own files (<name>.*), not the shared library, tables and "
      "manifest: one build action per material (docs/scaling.md)");
  app.add_flag("--shared-only", compile.shared_only,
               "Write only the shared files (matc_fresnel.*, the tables), from no material file: "
               "the one shared action beside per-material --no-shared actions")
      ->excludes(no_shared_option);
  app.add_option(
         "--lut", compile.lut_format,
         "File format of the tables DIR/matc_lut.<ext>, DIR/matc_coefficient_table.<ext> and "
         "DIR/matc_ltc.<ext>")
      ->capture_default_str()
      ->check(CLI::IsMember(matc::lut_format_names()));
  app.add_flag("--embed-lut", compile.embed_lut,
               "Also embed a small table in matc_fresnel.glsl/.hlsl as a constant array");
  app.add_option("--embed-lut-size", compile.embed_lut_size, "Width and height of that table")
      ->capture_default_str()
      ->check(CLI::Range(matc::kMinLutSize, matc::kMaxEmbeddedLutSize));
  add_lut_options(app, compile.lut, "lut-");
  add_color_options(app, compile.color);
  add_coefficient_table_option(app, compile.lut);
  app.add_flag("--validate", compile.validate,
               "Run each material's GLSL and HLSL shaders on a Vulkan device (lavapipe) against "
               "the CPU runtime before writing its files");
  const auto add_device_options = [](CLI::App& command, DeviceCliOptions& device) {
    command.add_flag("--vk-validation", device.layers,
                     "Enable the Khronos validation layer; any message it reports fails");
    command.add_option("--device", device.name,
                       "Use the Vulkan device whose name contains this (default: a GPU if any, "
                       "else lavapipe)");
  };
  add_device_options(app, compile.device);

  EvalOptions eval;
  CLI::App* eval_command =
      app.add_subcommand("eval", "Evaluate a material's decomposed and exact Fresnel as JSON");
  eval_command->add_option("file", eval.file,
                           "Material file (.json) or MaterialX document (.mtlx); or give "
                           "--reflectivity and --edge-tint");
  eval_command->add_option("--material", eval.material,
                           "Which material of a MaterialX document (its name as imported); needed "
                           "when the document holds more than one");
  eval_command->add_option("--reflectivity", eval.reflectivity,
                           "Gulbrandsen reflectivity r per channel (R,G,B or one grey value in "
                           "[0, 1]): F from the coefficient table beside the per-material compile");
  eval_command->add_option("--edge-tint", eval.edge_tint,
                           "Gulbrandsen edge tint g per channel, with --reflectivity");
  eval_command->add_option("--mu", eval.mu, "Cosines of incidence, comma-separated: F")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 1.0));
  CLI::Option* ndotv_option =
      eval_command->add_option("--ndotv", eval.ndotv, "NdotV values, comma-separated: Fbar")
          ->delimiter(',')
          ->check(CLI::Range(0.0, 1.0));
  CLI::Option* roughness_option =
      eval_command
          ->add_option("--roughness", eval.roughness,
                       "Perceptual roughness for each --ndotv value, comma-separated")
          ->delimiter(',')
          ->check(CLI::Range(0.0, 1.0));
  ndotv_option->needs(roughness_option);
  roughness_option->needs(ndotv_option);
  eval.light_samples = matc::kDefaultLightSamples;
  CLI::Option* no_reference_option = eval_command->add_flag(
      "--no-reference", eval.no_reference,
      "Leave out Fbar_reference, the exact split-sum integral per --ndotv value (a Monte-Carlo "
      "integral each: the slow part of evaluating many points)");
  eval_command
      ->add_option("--quad-light", eval.quad_light,
                   "A quad light of radiance 1, \"x,y,z;x,y,z;x,y,z;x,y,z\" in the shading frame "
                   "(normal +z, view in the xz-plane towards +x): radiance by LTC with ours and "
                   "with Schlick's Fresnel, and the exact integral (docs/ltc.md)")
      ->needs(ndotv_option)
      ->excludes(no_reference_option);
  eval_command
      ->add_option("--light-samples", eval.light_samples,
                   "Monte-Carlo sample pairs of the --quad-light reference")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{16}, std::size_t{1} << 26));
  add_lut_options(*eval_command, eval.lut, "lut-");
  add_coefficient_table_option(*eval_command, eval.lut);
  add_color_options(*eval_command, eval.color);

  ValidateOptions validate;
  CLI::App* validate_command = app.add_subcommand(
      "validate",
      "Run materials' generated shaders (GLSL and HLSL paths) on a Vulkan device and compare "
      "them with the CPU runtime; writes nothing");
  validate_command
      ->add_option("files", validate.files,
                   "Material files (.json) and MaterialX documents (.mtlx)")
      ->required();
  validate_command->add_flag("--embed-lut", validate.embed_lut,
                             "Also check the embedded-table path (lavapipe compiles tables "
                             "above 8x8 slowly: docs/validation.md)");
  validate_command
      ->add_option("--embed-lut-size", validate.embed_lut_size, "Width and height of that table")
      ->capture_default_str()
      ->check(CLI::Range(matc::kMinLutSize, matc::kMaxEmbeddedLutSize));
  add_lut_options(*validate_command, validate.lut, "lut-");
  add_coefficient_table_option(*validate_command, validate.lut);
  add_device_options(*validate_command, validate.device);
  add_color_options(*validate_command, validate.color);

  BasisOptions basis;
  CLI::App* basis_command = app.add_subcommand("basis", "Show the Fresnel basis b_0..b_3");
  basis_command->add_flag("--json", basis.json, "Print {mu, b, probes} as JSON");
  add_basis_option(*basis_command, basis.basis);
  // `matc basis` subcommands that regenerate checked-in C++ source: -o names where it lives.
  const auto add_source_command = [&](const char* name, const char* description,
                                      const char* checked_in, BasisFitOptions& options,
                                      bool per_basis) {
    CLI::App* command = basis_command->add_subcommand(name, description);
    command->add_option("-o,--output", options.output,
                        fmt::format("Where to write ({}); default stdout", checked_in));
    if (per_basis) add_basis_option(*command, options.basis);
    return command;
  };
  BasisFitOptions basis_fit;
  CLI::App* fit_command = add_source_command(
      "fit", "Refit the basis from its training set and write the C++ table source",
      "runtime/src/<basis>_basis_table.cpp", basis_fit, true);
  BasisFitOptions table_fit;
  CLI::App* table_fit_command = add_source_command(
      "coefficient-table",
      "Refit the coefficient table (c_2, c_3 over reflectivity and edge tint) and write its C++ "
      "source",
      "runtime/src/<basis>_coefficient_table.cpp", table_fit, true);
  BasisFitOptions analytic_lut;
  CLI::App* analytic_lut_command = add_source_command(
      "analytic-lut",
      "Bake the basis' default preintegrated table, fit its closed form (the albedo and a "
      "two-point quadrature of the basis, docs/shaders.md) and write the C++ source",
      "runtime/src/<basis>_analytic_lut_table.cpp", analytic_lut, true);
  BasisFitOptions lut_hashes;
  CLI::App* lut_hashes_command = add_source_command(
      "lut-hashes",
      "Bake the default preintegrated table of every basis and write the C++ source of its "
      "files' hashes (what headers and manifests name without baking)",
      "compiler/src/lut/default_lut_hashes.cpp", lut_hashes, false);
  BasisFitOptions material_modules;
  CLI::App* material_modules_command = add_source_command(
      "material-modules",
      "Compile every basis' material library module with placeholder coefficients and write the "
      "C++ source of those templates (what per-material SPIR-V is patched from)",
      "compiler/src/emit/material_module_templates.cpp", material_modules, false);
  LtcTableOptions ltc_table;
  CLI::App* ltc_table_command = basis_command->add_subcommand(
      "ltc-table",
      "Refit the LTC table of GGX (inverse matrices over NdotV and roughness, for area lights) "
      "and write its C++ source");
  ltc_table_command->add_option("-o,--output", ltc_table.output,
                                "Where to write (runtime/src/ltc_table.cpp); default stdout");
  ltc_table_command
      ->add_option("--quality", ltc_table.quality,
                   "Also write each texel's fit quality as CSV (distribution and polygon-light "
                   "errors: docs/ltc.md)")
      ->check(CLI::NonexistentPath | CLI::ExistingFile);
  ltc_table_command
      ->add_option("--quality-samples", ltc_table.quality_samples,
                   "Reference samples per polygon for --quality")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{64}, std::size_t{1} << 24));
  ltc_table_command->add_option("-j,--jobs", ltc_table.jobs, "Threads (default: one per core)");
  ltc_table_command
      ->add_option("--objective", ltc_table.objective,
                   "What the fit minimises: l1, the densities' L1 distance (shipped), or l3, "
                   "Heitz et al.'s cubed difference (for comparison)")
      ->capture_default_str()
      ->check(CLI::IsMember({"l1", "l3"}));

  LutCommandOptions lut;
  CLI::App* lut_command = app.add_subcommand(
      "lut", "Bake the preintegrated basis table (KTX2, DDS, raw or C++ header)");
  lut_command->add_option("-o,--output", lut.output, "Output file; a .json manifest goes beside it")
      ->required();
  lut_command->add_option("--format", lut.format, "File format (default: from the extension)")
      ->check(CLI::IsMember(matc::lut_format_names()));
  add_lut_options(*lut_command, lut.lut, "");

  BakeCommandOptions bake;
  CLI::App* bake_command = app.add_subcommand(
      "bake",
      "Bake reflectivity and edge-tint maps (or n and k maps) into coefficient textures with mip "
      "chains computed in coefficient space (KTX2 or DDS)");
  bake_command->add_option("files", bake.files, "Bake asset files (.json: docs/baking.md)");
  bake_command->add_option("--reflectivity", bake.reflectivity,
                           "Reflectivity map (PNG, JPEG, OpenEXR) or constant R,G,B / grey");
  bake_command->add_option("--edge-tint", bake.edge_tint,
                           "Edge-tint map or constant, with --reflectivity");
  bake_command->add_option("--n", bake.n, "Refractive index map (OpenEXR) or constant, with --k");
  bake_command->add_option("--k", bake.k, "Extinction coefficient map or constant, with --n");
  bake_command->add_option("--name", bake.name,
                           "Name of the command-line asset's files (default: the first map's "
                           "file name without extension)");
  bake_command->add_flag("--linear", bake.linear,
                         "The command-line maps hold linear values (default: PNG and JPEG "
                         "reflectivity and edge tint are sRGB-encoded; n, k are linear)");
  bake_command->add_option("-o,--output", bake.output_directory, "Output directory")
      ->capture_default_str();
  bake_command->add_option("--format", bake.format, "Texture file format")
      ->capture_default_str()
      ->check(CLI::IsMember({"ktx2", "dds"}));
  bake_command->add_option("--precision", bake.precision, "Texel precision")
      ->capture_default_str()
      ->check(CLI::IsMember({"f16", "f32"}));
  add_basis_option(*bake_command, bake.basis);
  bake_command->add_flag("--f0", bake.f0,
                         "Also write NAME_f0 (linear F0 with coefficient-space mips), for "
                         "engines whose base-colour mips are not box averages of linear F0");
  bake_command->add_flag("--error-map", bake.error_map,
                         "Also write NAME_error.png: level 0's largest |F - exact| per texel "
                         "(255 = 0.01 or more)");
  bake_command->add_flag("-k,--keep-going", bake.keep_going,
                         "Bake the remaining assets after one fails (still exits 1)");
  bake_command->add_flag("-q,--quiet", bake.quiet, "Do not print the progress and summary lines");
  bake_command->add_option("-j,--jobs", bake.jobs, "Threads (default: one per hardware thread)")
      ->check(CLI::Range(1u, 1024u));
  bake_command->add_option("--depfile", bake.depfile,
                           "Write the outputs' dependencies (asset files, maps, the matc "
                           "binary) to FILE in the Makefile syntax Ninja and CMake read");
  bake_command->add_flag("--MD", bake.write_depfile, "The same, as DIR/matc_bake.d");

  ReportOptions report;
  CLI::App* report_command = app.add_subcommand(
      "report",
      "Plot each material's Fresnel curves (exact, ours, Schlick, F82-tint) as SVG, with CSV "
      "samples and an HTML index of the errors");
  report_command->add_option("files", report.files, "Material files (.json), MaterialX documents")
      ->required();
  report_command->add_option("-o,--output", report.output_directory, "Output directory")
      ->capture_default_str();
  add_basis_option(*report_command, report.basis);
  add_color_options(*report_command, report.color);

  ImportOptions import;
  CLI::App* import_command = app.add_subcommand(
      "import",
      "Write a matc material file for each metallic Standard Surface or OpenPBR material of "
      "MaterialX documents (docs/interchange.md)");
  import_command->add_option("files", import.files, "MaterialX documents (.mtlx)")->required();
  import_command->add_option("-o,--output", import.output_directory, "Output directory")
      ->capture_default_str();
  import_command->add_flag("-k,--keep-going", import.keep_going,
                           "Write the other documents' materials when one fails (still exits 1)");
  import_command->add_flag("-q,--quiet", import.quiet, "Do not print the summary line");

  // -MD, as compilers spell it: CLI11 only takes one-letter names after a single dash.
  std::vector<std::string> arguments(argv + 1, argv + argc);
  std::replace(arguments.begin(), arguments.end(), std::string("-MD"), std::string("--MD"));
  std::reverse(arguments.begin(), arguments.end());  // CLI11's order for a vector
  std::string diagnostics_format = "text";
  for (CLI::App* command :
       {&app, eval_command, validate_command, report_command, bake_command, import_command}) {
    command
        ->add_option("--diagnostics-format", diagnostics_format,
                     "How problems in inputs are reported on standard error: text "
                     "(file:line:col: error: ...) or json (one object per line)")
        ->check(CLI::IsMember({"text", "json"}));
  }
  try {
    app.parse(arguments);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion&) {
    fmt::print("matc {}\n", matc::kVersion);
    return kExitSuccess;
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsageError;
  }

  set_diagnostics_format(diagnostics_format == "json" ? DiagnosticsFormat::json
                                                      : DiagnosticsFormat::text);
  try {
    if (*eval_command) return run_eval(eval);
    if (*bake_command) return run_bake(bake);
    if (*lut_command) return run_lut(lut);
    if (*validate_command) return run_validate(validate);
    if (*report_command) return run_report(report);
    if (*import_command) return run_import(import);
    if (*fit_command) return run_basis_fit(basis_fit);
    if (*table_fit_command) return run_basis_coefficient_table(table_fit);
    if (*ltc_table_command) return run_basis_ltc_table(ltc_table);
    if (*lut_hashes_command) return run_basis_lut_hashes(lut_hashes);
    if (*analytic_lut_command) return run_basis_analytic_lut(analytic_lut);
    if (*material_modules_command) return run_basis_material_modules(material_modules);
    if (*basis_command) return run_basis(basis);
    if (!files_from.empty()) {
      const std::optional<std::vector<std::string>> listed = read_file_list(files_from);
      if (!listed) {
        fmt::print(stderr, "{}: error: --files-from: cannot read the list\n", files_from);
        return kExitUsageError;
      }
      compile.files.insert(compile.files.end(), listed->begin(), listed->end());
    }
    if (compile.shared_only && !compile.files.empty()) {
      fmt::print(stderr,
                 "matc: error: --shared-only writes no material's files; give no material file "
                 "(compile materials with --no-shared in their own runs)\n");
      return kExitUsageError;
    }
    if (compile.files.empty() && !compile.shared_only) {
      fmt::print(stderr,
                 "matc: error: no material files given; usage: matc [-o DIR] FILES... "
                 "(see matc --help)\n");
      return kExitUsageError;
    }
    return run_compile(compile);
  } catch (const std::exception& error) {
    fmt::print(stderr, "matc: internal error: {}\n", error.what());
    return kExitInternalError;
  }
}
