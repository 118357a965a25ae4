#include "matc/api/compiled_material.h"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "checked_options.h"
#include "matc/compile/compile.h"
#include "matc/lut/preintegrate.h"
#include "matc/optics/coat.h"
#include "matc/optics/fresnel.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/shader_basis.h"
#include "public_diagnostics.h"

namespace matc::api {

// What the evaluations need beside the compiled value: the basis, and the exact curves the
// coefficients were fitted to (the material in air and, for a coated one, the metal under its
// coat and both layered, which refers to the other two).
struct CompiledMaterial::Evaluation {
  runtime::BasisKind basis = runtime::kDefaultBasis;
  std::unique_ptr<ReflectanceCurve> in_air;
  std::unique_ptr<ReflectanceCurve> under_coat;
  std::unique_ptr<ReflectanceCurve> layered;
  const ReflectanceCurve& exact() const { return layered ? *layered : *in_air; }
};

namespace {

void check_unit_interval(std::string_view argument, std::span<const double> values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!(values[i] >= 0.0 && values[i] <= 1.0)) {
      throw std::invalid_argument(
          fmt::format("{}: element {} is {}; a number in [0, 1]", argument, i, values[i]));
    }
  }
}

template <typename RgbAt>
std::vector<double> rgb_per_cosine(std::span<const double> mu, const RgbAt& rgb_at) {
  check_unit_interval("mu", mu);
  std::vector<double> rgb(3 * mu.size());
  for (std::size_t i = 0; i < mu.size(); ++i) {
    const Rgb value = rgb_at(mu[i]);
    for (std::size_t c = 0; c < 3; ++c)
      rgb[3 * i + c] = value[c];
  }
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

Accuracy CompiledMaterial::accuracy() const {
  const FitAccuracy& fit = value_->accuracy;
  return {fit.samples,     fit.decomposition.max_abs, fit.decomposition.rms, fit.schlick.max_abs,
          fit.schlick.rms, fit.f82_tint.max_abs,      fit.f82_tint.rms};
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
  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(evaluation_->basis);
  if (const auto& coat = value_->coat) {
    return rgb_per_cosine(mu, [&](double cosine) {
      return runtime::evaluate_coated_fresnel(value_->coefficients, coat->coefficients,
                                              shader_basis, cosine)
          .total();
    });
  }
  check_unit_interval("mu", mu);
  std::vector<double> rgb(3 * mu.size());
  runtime::evaluate_fresnel(value_->coefficients, shader_basis, mu, rgb);
  return rgb;
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
    const runtime::CoatedFresnel f = runtime::evaluate_coated_fresnel(
        value_->coefficients, value_->coat->coefficients, shader_basis, mu[i]);
    for (std::size_t c = 0; c < 3; ++c)
      lobes.base[3 * i + c] = f.base[c];
    lobes.coat[i] = f.coat;
  }
  return lobes;
}

std::vector<double> CompiledMaterial::fbar(std::span<const double> ndotv,
                                           std::span<const double> roughness) const {
  if (ndotv.size() != roughness.size()) {
    throw std::invalid_argument(
        fmt::format("ndotv and roughness: {} and {} values; one roughness per NdotV", ndotv.size(),
                    roughness.size()));
  }
  check_unit_interval("ndotv", ndotv);
  check_unit_interval("roughness", roughness);
  const runtime::LutView table = default_table(evaluation_->basis).view();
  std::vector<double> rgb(3 * ndotv.size());
  for (std::size_t i = 0; i < ndotv.size(); ++i) {
    const Rgb value =
        value_->coat
            ? runtime::evaluate_coated_fbar(value_->coefficients, value_->coat->coefficients, table,
                                            ndotv[i], roughness[i])
                  .total()
            : runtime::evaluate_fbar(value_->coefficients, table, ndotv[i], roughness[i]);
    for (std::size_t c = 0; c < 3; ++c)
      rgb[3 * i + c] = value[c];
  }
  return rgb;
}

CompiledMaterial compile(const Material& material, const CompileOptions& options) {
  const runtime::BasisKind basis = basis_of(options);
  const ColorOptions color = color_options_of(options);
  const matc::Material& value = material.value();
  auto compiled = std::make_shared<matc::CompiledMaterial>(
      compile_material(value, runtime::shipped_basis(basis), color));
  auto evaluation = std::make_shared<CompiledMaterial::Evaluation>();
  evaluation->basis = basis;
  evaluation->in_air = make_reflectance_curve(value, color);
  if (const auto& coat = compiled->coat) {
    evaluation->under_coat = make_under_coat_curve(value, color.working_space);
    evaluation->layered =
        std::make_unique<LayeredCurve>(*evaluation->in_air, *evaluation->under_coat,
                                       coat->input.weight, coat->input.ior, coat->input.color);
  }
  Diagnostics diagnostics;
  warn_if_poor_fit(*compiled, diagnostics);
  note_if_out_of_unit_range(*compiled, diagnostics);
  std::vector<Diagnostic> all = material.diagnostics();
  for (Diagnostic& diagnostic : public_diagnostics(diagnostics))
    all.push_back(std::move(diagnostic));
  return CompiledMaterial(material, std::move(compiled), std::move(evaluation), std::move(all));
}

}  // namespace matc::api
