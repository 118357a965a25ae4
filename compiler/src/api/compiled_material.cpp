#include "matc/api/compiled_material.h"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "base/json_format.h"
#include "checked_options.h"
#include "checked_values.h"
#include "compile/compile.h"
#include "compiled_evaluation.h"
#include "emit/material_json.h"
#include "lut/preintegrate.h"
#include "matc/api/tables.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/film_table.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/shader_basis.h"
#include "optics/coat.h"
#include "optics/fresnel.h"
#include "public_diagnostics.h"

namespace matc::api {

namespace {

// rgb_at(mu) at each cosine into `rgb`, 3 values per cosine (the caller checked both).
template <typename RgbAt>
void write_rgb_per_cosine(std::span<const double> mu, std::span<double> rgb, const RgbAt& rgb_at) {
  for (std::size_t i = 0; i < mu.size(); ++i) {
    const Rgb value = rgb_at(mu[i]);
    for (std::size_t c = 0; c < 3; ++c)
      rgb[3 * i + c] = value[c];
  }
}

template <typename RgbAt>
std::vector<double> rgb_per_cosine(std::span<const double> mu, const RgbAt& rgb_at) {
  check_unit_interval("mu", mu);
  std::vector<double> rgb(3 * mu.size());
  write_rgb_per_cosine(mu, rgb, rgb_at);
  return rgb;
}

// The split-sum table of each basis at the default size, baked once and kept.
const Lut& default_table(runtime::BasisKind basis) {
  static std::mutex mutex;
  static std::map<runtime::BasisKind, Lut> tables;
  const std::lock_guard lock(mutex);
  auto found = tables.find(basis);
  if (found == tables.end())
    found = tables.emplace(basis, preintegrate_lut(runtime::shipped_basis(basis))).first;
  return found->second;
}

void check_rgb_size(std::span<double> rgb, std::size_t count) {
  if (rgb.size() != 3 * count) {
    throw std::invalid_argument(
        fmt::format("rgb: {} values for {} inputs; 3 per input (R, G, B)", rgb.size(), count));
  }
}

// Fbar at each pair from `table` into rgb, as the shaders fetch it (a coated material's lobes
// summed; a filmed one's base from its own tables, whatever the table).
void fbar_from_table(const matc::CompiledMaterial& compiled, std::span<const double> ndotv,
                     std::span<const double> roughness, const runtime::LutView& table,
                     std::span<double> rgb) {
  check_ndotv_roughness(ndotv, roughness);
  check_rgb_size(rgb, ndotv.size());
  for (std::size_t i = 0; i < ndotv.size(); ++i) {
    const Rgb value =
        compiled.coat && compiled.film_table
            ? runtime::evaluate_film_coated_fbar(*compiled.film_table, compiled.coat->coefficients,
                                                 table, ndotv[i], roughness[i])
                  .total()
        : compiled.film_table
            ? runtime::film_preintegrated(*compiled.film_table, ndotv[i], roughness[i])
        : compiled.coat
            ? runtime::evaluate_coated_fbar(compiled.coefficients, compiled.coat->coefficients,
                                            table, ndotv[i], roughness[i])
                  .total()
            : runtime::evaluate_fbar(compiled.coefficients, table, ndotv[i], roughness[i]);
    for (std::size_t c = 0; c < 3; ++c)
      rgb[3 * i + c] = value[c];
  }
}

}  // namespace

CompiledMaterial::CompiledMaterial(Material material,
                                   std::shared_ptr<const matc::CompiledMaterial> value,
                                   std::shared_ptr<const Evaluation> evaluation,
                                   std::vector<Diagnostic> diagnostics)
    : material_(std::move(material)),
      value_(std::move(value)),
      evaluation_(std::move(evaluation)),
      diagnostics_(std::move(diagnostics)) {}

const std::string& CompiledMaterial::name() const {
  return material_.name();
}
std::string CompiledMaterial::basis() const {
  return std::string(runtime::basis_name(evaluation_->basis));
}
const CoefficientRows& CompiledMaterial::coefficients() const {
  return value_->coefficients;
}
Rgb CompiledMaterial::f0() const {
  return value_->f0;
}
Rgb CompiledMaterial::f82() const {
  return value_->f82;
}

Rgb CompiledMaterial::average_fresnel() const {
  return value_->average_fresnel;
}

std::string CompiledMaterial::color_space() const {
  return std::string(color_space_name(value_->color.working_space));
}
std::string CompiledMaterial::gamut_mapping() const {
  return std::string(gamut_mapping_name(value_->color.gamut_mapping));
}

std::optional<ComplexIor> CompiledMaterial::ior() const {
  if (!value_->ior) return std::nullopt;
  ComplexIor ior;
  for (std::size_t c = 0; c < 3; ++c) {
    ior.n[c] = (*value_->ior)[c].n;
    ior.k[c] = (*value_->ior)[c].k;
  }
  return ior;
}

std::optional<ArtisticParameters> CompiledMaterial::artistic() const {
  if (!value_->artistic) return std::nullopt;
  ArtisticParameters artistic;
  for (std::size_t c = 0; c < 3; ++c) {
    artistic.reflectivity[c] = (*value_->artistic)[c].reflectivity;
    artistic.edge_tint[c] = (*value_->artistic)[c].edge_tint;
  }
  return artistic;
}

double CompiledMaterial::saturation() const {
  return value_->saturation;
}
bool CompiledMaterial::fresnel_nonnegative() const {
  return value_->fresnel_nonnegative;
}

std::string CompiledMaterial::json() const {
  return format_json(compiled_material_json(*value_, runtime::shipped_basis(evaluation_->basis),
                                            evaluation_->per_material_build));
}

std::optional<FilmTable> CompiledMaterial::film_table() const {
  if (!value_->film_table) return std::nullopt;
  return FilmTable{runtime::FilmTable::kWidth, runtime::FilmTable::kHeight,
                   runtime::film_table_texels(*value_->film_table)};
}

Accuracy CompiledMaterial::accuracy() const {
  const FitAccuracy& fit = value_->accuracy;
  // What the shaders compute: a filmed metal's tables, else the decomposition.
  const ErrorStats& ours = shader_fresnel_error(*value_);
  return {fit.samples,     ours.max_abs,         ours.rms,        fit.schlick.max_abs,
          fit.schlick.rms, fit.f82_tint.max_abs, fit.f82_tint.rms};
}

std::optional<Coat> CompiledMaterial::coat() const {
  if (!value_->coat) return std::nullopt;
  const CompiledCoat& coat = *value_->coat;
  return Coat{coat.input.weight,
              coat.input.ior,
              coat.input.roughness,
              coat.input.color,
              coat.coefficients.under_coat,
              coat.coefficients.coat,
              coat.layered_error.max_abs};
}

std::vector<double> CompiledMaterial::fresnel(std::span<const double> mu) const {
  std::vector<double> rgb(3 * mu.size());
  fresnel(mu, rgb);
  return rgb;
}

void CompiledMaterial::fresnel(std::span<const double> mu, std::span<double> rgb) const {
  check_unit_interval("mu", mu);
  check_rgb_size(rgb, mu.size());
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(evaluation_->basis);
  // A layered or filmed material per cosine; a bare one through the span form.
  if (value_->coat || value_->film_table) {
    write_rgb_per_cosine(
        mu, rgb, [&](double cosine) { return shader_fresnel(*value_, shader_basis, cosine); });
    return;
  }
  runtime::evaluate_fresnel(value_->coefficients, shader_basis, mu, rgb);
}

std::vector<double> CompiledMaterial::exact(std::span<const double> mu) const {
  const ReflectanceCurve& curve = evaluation_->exact();
  return rgb_per_cosine(mu, [&](double cosine) { return curve.at(cosine); });
}

std::vector<double> CompiledMaterial::schlick(std::span<const double> mu) const {
  const Rgb f0 = value_->f0;
  return rgb_per_cosine(mu, [&](double cosine) {
    return Rgb{fresnel_schlick(cosine, f0[0]), fresnel_schlick(cosine, f0[1]),
               fresnel_schlick(cosine, f0[2])};
  });
}

std::vector<double> CompiledMaterial::f82_tint(std::span<const double> mu) const {
  const Rgb f0 = value_->f0, f82 = value_->f82;
  return rgb_per_cosine(mu, [&](double cosine) {
    return Rgb{fresnel_f82_tint(cosine, f0[0], f82[0]), fresnel_f82_tint(cosine, f0[1], f82[1]),
               fresnel_f82_tint(cosine, f0[2], f82[2])};
  });
}

CompiledMaterial::Lobes CompiledMaterial::coated_fresnel(std::span<const double> mu) const {
  if (!value_->coat) {
    throw std::logic_error(
        fmt::format("coated_fresnel: {} has no coat; fresnel gives its F", echoed(name())));
  }
  check_unit_interval("mu", mu);
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(evaluation_->basis);
  Lobes lobes{std::vector<double>(3 * mu.size()), std::vector<double>(mu.size())};
  for (std::size_t i = 0; i < mu.size(); ++i) {
    const runtime::CoatedFresnel f = shader_coated_fresnel(*value_, shader_basis, mu[i]);
    for (std::size_t c = 0; c < 3; ++c)
      lobes.base[3 * i + c] = f.base[c];
    lobes.coat[i] = f.coat;
  }
  return lobes;
}

std::vector<double> CompiledMaterial::fbar(std::span<const double> ndotv,
                                           std::span<const double> roughness) const {
  std::vector<double> rgb(3 * ndotv.size());
  fbar(ndotv, roughness, rgb);
  return rgb;
}

std::vector<double> CompiledMaterial::fbar(std::span<const double> ndotv,
                                           std::span<const double> roughness,
                                           const PreintegratedTable& table) const {
  std::vector<double> rgb(3 * ndotv.size());
  fbar(ndotv, roughness, table, rgb);
  return rgb;
}

void CompiledMaterial::fbar(std::span<const double> ndotv, std::span<const double> roughness,
                            std::span<double> rgb) const {
  fbar_from_table(*value_, ndotv, roughness, default_table(evaluation_->basis).view(), rgb);
}

void CompiledMaterial::fbar(std::span<const double> ndotv, std::span<const double> roughness,
                            const PreintegratedTable& table, std::span<double> rgb) const {
  if (table.basis() != basis()) {
    throw std::invalid_argument(
        fmt::format("table: integrates the {} basis; this material is compiled against {}",
                    table.basis(), basis()));
  }
  fbar_from_table(*value_, ndotv, roughness, table.value().view(), rgb);
}

CompileOptions default_compile_options() {
  return {std::string(option_name(BasisChoice{})),
          std::string(color_space_name(kDefaultColorSpace)),
          std::string(gamut_mapping_name(GamutMapping::none))};
}

std::vector<double> fresnel_from_coefficients(const CoefficientRows& coefficients,
                                              std::span<const double> mu, std::string_view basis) {
  const runtime::BasisKind kind = basis_of({std::string(basis), {}, {}});
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < runtime::kBasisSize; ++i) {
      if (!std::isfinite(coefficients[c][i])) {
        throw std::invalid_argument(
            fmt::format("coefficients: [{}, {}] is {}; a finite number", c, i, coefficients[c][i]));
      }
    }
  }
  check_unit_interval("mu", mu);
  std::vector<double> rgb(3 * mu.size());
  runtime::evaluate_fresnel(coefficients, runtime::shipped_shader_basis(kind), mu, rgb);
  return rgb;
}

const CompiledMaterial::Evaluation::Curves& CompiledMaterial::Evaluation::curves() const {
  std::call_once(made_, [this] {
    curves_.in_air = make_reflectance_curve(*material, color);
    if (const auto& coat = material->coat) {
      curves_.under_coat = make_under_coat_curve(*material, color.working_space);
      curves_.layered = std::make_unique<LayeredCurve>(*curves_.in_air, *curves_.under_coat,
                                                       coat->weight, coat->ior, coat->color);
    }
  });
  return curves_;
}

namespace {

// The evaluations of `compiled` (compiled in a build of `choice`): its exact curves made from the
// material the compiled value holds, shared with it.
std::shared_ptr<const CompiledMaterial::Evaluation> evaluation_of(
    const std::shared_ptr<const matc::CompiledMaterial>& compiled, const BasisChoice& choice) {
  auto evaluation = std::make_shared<CompiledMaterial::Evaluation>();
  evaluation->basis = compiled->basis;
  evaluation->per_material_build = choice.per_material;
  evaluation->color = compiled->color;
  evaluation->material = std::shared_ptr<const matc::Material>(compiled, &compiled->material);
  return evaluation;
}

}  // namespace

CompiledMaterial public_compiled(std::shared_ptr<const matc::CompiledMaterial> compiled,
                                 const BasisChoice& choice, std::vector<Diagnostic> diagnostics) {
  auto evaluation = evaluation_of(compiled, choice);
  Material material(evaluation->material, {});
  return CompiledMaterial(std::move(material), std::move(compiled), std::move(evaluation),
                          std::move(diagnostics));
}

CompiledMaterial compile(const Material& material, const CompileOptions& options) {
  const matc::Material& value = material.value();
  const BasisChoice choice = basis_choice_of(options);
  const ColorOptions color = color_options_of(options);
  auto compiled = std::make_shared<const matc::CompiledMaterial>(
      compile_material(value, runtime::shipped_basis(chosen_basis(value, choice)), color));
  auto evaluation = evaluation_of(compiled, choice);
  Diagnostics diagnostics;
  warn_if_poor_fit(*compiled, diagnostics);
  note_if_out_of_unit_range(*compiled, diagnostics);
  std::vector<Diagnostic> all = material.diagnostics();
  for (Diagnostic& diagnostic : public_diagnostics(diagnostics))
    all.push_back(std::move(diagnostic));
  return CompiledMaterial(material, std::move(compiled), std::move(evaluation), std::move(all));
}

}  // namespace matc::api
