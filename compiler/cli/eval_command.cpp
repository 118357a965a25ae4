// matc eval: the public API's evaluate (matc/api/evaluation.h) of a material file's material, or
// of the coefficient-table path, printed as JSON.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "commands.h"
#include "matc/api/evaluation.h"
#include "matc/api/options.h"
#include "matc/matc.h"
#include "name_options.h"
#include "option_help.h"
#include "print_diagnostics.h"

namespace matc::cli {
namespace {

struct EvalOptions {
  std::string file;          // a material file or MaterialX document, or:
  std::string material;      // --material: which of a document's materials
  std::string reflectivity;  // --reflectivity and --edge-tint: the coefficient-table path
  std::string edge_tint;
  std::string quad_light;     // "x,y,z;x,y,z;x,y,z;x,y,z" in the shading frame: area-light radiance
  bool no_reference = false;  // --no-reference: no Monte-Carlo references, the shaders' values
  double metalness = 0;       // --metalness, when given: glTF's metal-rough mix
  double film_thickness = 0;  // --film-thickness, when given: a thickness per pixel's film
  api::EvaluationOptions evaluation;
};

// The evaluation's table, basis and colour options, as the other commands name them.
void add_evaluation_options(CLI::App& app, api::EvaluationOptions& options) {
  app.add_option("--lut-size", options.lut_size, kLutSizeHelp)
      ->capture_default_str()
      ->check(CLI::Range(api::kMinLutSize, api::kMaxLutSize));
  app.add_option("--lut-samples", options.lut_samples, kLutSamplesHelp)
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{1}, api::kMaxLutSamples));
  add_name_option(app, "--lut-precision", options.lut_precision, "lut_precision",
                  kLutPrecisionHelp);
  add_name_option(app, "--basis", options.compile.basis, "build_basis", kBuildBasisHelp,
                  api::option_default("build_basis"));
  add_name_option(app, "--coefficient-table-precision", options.coefficient_table_precision,
                  "lut_precision", kCoefficientTablePrecisionHelp, "f16");
  add_color_name_options(app, options.compile);
}

// The quad of --quad-light into the options, or false with the problem printed.
bool read_quad_light(EvalOptions& options) {
  if (options.quad_light.empty()) return true;
  try {
    options.evaluation.quad_light = api::parse_quad_light(options.quad_light);
    return true;
  } catch (const std::invalid_argument& error) {
    fmt::print(stderr, "matc eval: error: --quad-light: {}\n", error.what());
    return false;
  }
}

// Prints what `evaluate` returns; an option the library refuses (a NaN that CLI11's ranges let
// through, say) is a usage error naming it.
template <typename Evaluate>
int print_evaluation(const Evaluate& evaluate) {
  std::string text;
  try {
    text = evaluate();
  } catch (const std::invalid_argument& error) {
    fmt::print(stderr, "matc eval: error: {}\n", api::printable(error.what()));
    return kExitUsageError;
  }
  fmt::print("{}", text);
  return kExitSuccess;
}

// `matc eval --reflectivity R --edge-tint G`: the coefficient-table path beside the compile.
int run_eval_artistic(EvalOptions& options) {
  if (!options.file.empty()) {
    fmt::print(stderr,
               "matc eval: error: give a material file, or --reflectivity with --edge-tint, not "
               "both\n");
    return kExitUsageError;
  }
  if (options.reflectivity.empty() || options.edge_tint.empty()) {
    fmt::print(stderr, "matc eval: error: --reflectivity and --edge-tint go together: give both\n");
    return kExitUsageError;
  }
  api::Rgb reflectivity{}, edge_tint{};
  try {
    reflectivity = api::parse_channel_values("--reflectivity", options.reflectivity);
    edge_tint = api::parse_channel_values("--edge-tint", options.edge_tint);
  } catch (const std::invalid_argument& error) {
    fmt::print(stderr, "matc eval: error: {}\n", error.what());
    return kExitInputError;
  }
  if (!read_quad_light(options)) return kExitInputError;
  if (options.evaluation.metalness) {
    fmt::print(stderr,
               "matc eval: error: --metalness mixes a material's metal; the coefficient-table "
               "path (--reflectivity, --edge-tint) has none\n");
    return kExitUsageError;
  }
  return print_evaluation(
      [&] { return api::evaluate_artistic(reflectivity, edge_tint, options.evaluation); });
}

// The material to evaluate: the file's only one, or the document's material named --material.
std::optional<api::Material> chosen_material(const EvalOptions& options) {
  std::vector<api::Material> materials;
  try {
    materials = api::load_materials(options.file);
  } catch (const api::MaterialError& error) {
    print_diagnostics(error.diagnostics());
    return std::nullopt;
  }
  if (materials.empty()) return std::nullopt;
  print_diagnostics(materials.front().diagnostics());  // the input's, which every material holds
  std::string names;
  for (const api::Material& material : materials) {
    if (material.name() == options.material || (options.material.empty() && materials.size() == 1))
      return material;
    names += fmt::format("{}{}", names.empty() ? "" : ", ", material.name());
  }
  if (options.material.empty()) {
    fmt::print(stderr, "matc eval: error: {} holds {} materials ({}): name one with --material\n",
               api::printable(options.file), materials.size(), names);
  } else {
    fmt::print(stderr, "matc eval: error: --material: {} holds no material '{}' (it holds {})\n",
               api::printable(options.file), api::echoed(options.material), names);
  }
  return std::nullopt;
}

int run_eval(EvalOptions& options) {
  api::EvaluationOptions& evaluation = options.evaluation;
  evaluation.reference = !options.no_reference;
  if (evaluation.mu.empty() && evaluation.ndotv.empty()) {
    fmt::print(stderr, "matc eval: error: give --mu and/or --ndotv with --roughness\n");
    return kExitUsageError;
  }
  if (evaluation.ndotv.size() != evaluation.roughness.size()) {
    fmt::print(stderr,
               "matc eval: error: --ndotv has {} values and --roughness {}; they pair up, so "
               "give as many of each\n",
               evaluation.ndotv.size(), evaluation.roughness.size());
    return kExitUsageError;
  }
  if (!options.reflectivity.empty() || !options.edge_tint.empty())
    return run_eval_artistic(options);
  if (options.file.empty()) {
    fmt::print(stderr,
               "matc eval: error: give a material file, or --reflectivity with --edge-tint\n");
    return kExitUsageError;
  }
  if (!read_quad_light(options)) return kExitInputError;
  const std::optional<api::Material> material = chosen_material(options);
  if (!material) return kExitInputError;
  return print_evaluation([&] { return api::evaluate(*material, evaluation); });
}

}  // namespace

Command register_eval(CLI::App& app) {
  auto options = std::make_shared<EvalOptions>();
  CLI::App* command =
      app.add_subcommand("eval", "Evaluate a material's decomposed and exact Fresnel as JSON");
  command->add_option("file", options->file,
                      "Material file (.json) or MaterialX document (.mtlx); or give "
                      "--reflectivity and --edge-tint");
  command->add_option("--material", options->material,
                      "Which material of a MaterialX document (its name as imported); needed "
                      "when the document holds more than one");
  command->add_option("--reflectivity", options->reflectivity,
                      "Gulbrandsen reflectivity r per channel (R,G,B or one grey value in "
                      "[0, 1]): F from the coefficient table beside the per-material compile");
  command->add_option("--edge-tint", options->edge_tint,
                      "Gulbrandsen edge tint g per channel, with --reflectivity");
  command->add_option("--mu", options->evaluation.mu, "Cosines of incidence, comma-separated: F")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 1.0));
  CLI::Option* ndotv_option =
      command
          ->add_option("--ndotv", options->evaluation.ndotv, "NdotV values, comma-separated: Fbar")
          ->delimiter(',')
          ->check(CLI::Range(0.0, 1.0));
  CLI::Option* roughness_option =
      command
          ->add_option("--roughness", options->evaluation.roughness,
                       "Perceptual roughness for each --ndotv value, comma-separated")
          ->delimiter(',')
          ->check(CLI::Range(0.0, 1.0));
  ndotv_option->needs(roughness_option);
  roughness_option->needs(ndotv_option);
  command->add_flag(
      "--no-reference", options->no_reference,
      "Leave out the references: Fbar_reference, the exact split-sum integral per --ndotv "
      "value (a Monte-Carlo integral each: the slow part of evaluating many points), a coated "
      "material's layered ones, and --quad-light's L_reference and L_ltc_exact_fresnel");
  command
      ->add_option("--quad-light", options->quad_light,
                   "A quad light of radiance 1, \"x,y,z;x,y,z;x,y,z;x,y,z\" in the shading frame "
                   "(normal +z, view in the xz-plane towards +x): radiance by LTC with ours (one "
                   "shape, and the quality level's shape and Fresnel following the light) and "
                   "with Schlick's Fresnel, and the exact integral (docs/ltc.md)")
      ->needs(ndotv_option);
  command
      ->add_option("--light-samples", options->evaluation.light_samples,
                   "Monte-Carlo sample pairs of the --quad-light reference")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{16}, std::size_t{1} << 26));
  CLI::Option* metalness_option =
      command
          ->add_option("--metalness", options->metalness,
                       "glTF's metal-rough model (docs/gltf.md): F and Fbar of the metal mixed "
                       "by this metalness with glTF's dielectric (F0 0.04, F90 1), as "
                       "matc_metal_rough computes them")
          ->check(CLI::Range(0.0, 1.0));
  CLI::Option* film_thickness_option =
      command->add_option("--film-thickness", options->film_thickness,
                          "a thickness per pixel (docs/thin-film.md): the film at this thickness "
                          "in nanometres, within the material's range, as its shaders read it");
  add_evaluation_options(*command, options->evaluation);

  return {command,
          [options, metalness_option, film_thickness_option] {
            if (metalness_option->count() > 0) options->evaluation.metalness = options->metalness;
            if (film_thickness_option->count() > 0)
              options->evaluation.film_thickness = options->film_thickness;
            return run_eval(*options);
          },
          true};
}

}  // namespace matc::cli
