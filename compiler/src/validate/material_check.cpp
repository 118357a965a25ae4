// The material check: one material's generated code (F, Fbar through the sampler, from the
// embedded table, from the closed form) against the CPU runtime.
#include <cmath>

#include <fmt/format.h>

#include "emit/validation_kernel.h"
#include "largest_difference.h"
#include "lut/film_table_files.h"
#include "matc/runtime/analytic_lut.h"
#include "matc/runtime/coat.h"
#include "matc/runtime/film_table.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/metal_rough.h"
#include "matc/runtime/shader_basis.h"
#include "validate/device_validator.h"

namespace matc {
namespace {

constexpr std::size_t kGridSteps = 40;  // 41 points per axis

class MaterialCheck final : public DeviceCheck {
 public:
  MaterialCheck(const Build& build, const CompiledMaterial& compiled,
                const ValidationTolerance& tolerance)
      : build_(build), compiled_(compiled), tolerance_(tolerance), queries_(validation_queries()) {
    if (compiled.film_table)
      stored_film_ = stored_as(*compiled.film_table, build.options().lut_precision);
    if (compiled.film_stack)
      stored_stack_ = stored_as(*compiled.film_stack, build.options().lut_precision);
  }

  std::string subject() const override { return compiled_.material.name; }

  SpirvWords kernel(ShaderLanguage language) const override {
    return material_validation_module(build_, language, compiled_);
  }

  std::size_t query_count() const override { return queries_.size(); }

  std::vector<float> packed_queries() const override {
    std::vector<float> packed;
    packed.reserve(queries_.size() * 4);
    for (std::size_t i = 0; i < queries_.size(); ++i) {
      const ValidationQuery& q = queries_[i];
      packed.insert(packed.end(), {q.mu, q.ndotv, q.roughness, thickness_of(i)});
    }
    return packed;
  }

  std::size_t result_vec4s_per_query() const override {
    switch (material_kernel_of(compiled_)) {
      case MaterialKernel::coated:
        return kCoatedValidationResultsPerQuery;
      case MaterialKernel::filmed:
      case MaterialKernel::film_stack:
        return kFilmValidationResultsPerQuery;
      case MaterialKernel::film_coated:
        return kFilmCoatedValidationResultsPerQuery;
      case MaterialKernel::bare:
        break;
    }
    return kValidationResultsPerQuery;
  }

  // A coated material's kernel lights both lobes with a quad light through the LTC table; a
  // filmed one's samples its own table and lights it so too.
  KernelTables tables() const override {
    KernelTables tables{false, compiled_.coat.has_value() || stored_film_.has_value(), {}};
    if (stored_stack_)
      tables.film = runtime::film_stack_texels(*stored_stack_);
    else if (stored_film_)
      tables.film = runtime::film_table_texels(*stored_film_);
    return tables;
  }

  std::vector<CheckedQuantity> compare(std::span<const float> results) const override {
    // The material's basis, its layer of the table and its closed form.
    const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(compiled_.basis);
    const runtime::LutView table = build_.stored_lut(compiled_.basis).view();
    const Lut* embedded = build_.embedded_lut(compiled_.basis);
    const runtime::AnalyticLutCoefficients& analytic =
        runtime::shipped_analytic_lut(compiled_.basis);
    if (compiled_.coat && stored_film_)
      return compare_film_coated(results, *stored_film_, shader_basis, table);
    if (compiled_.coat) return compare_coated(results, shader_basis, table, embedded, analytic);
    if (stored_stack_) {
      runtime::FilmTable at_thickness;
      return compare_filmed(results, [&](std::size_t i) -> const runtime::FilmTable& {
        at_thickness = runtime::film_stack_table_at(*stored_stack_, thickness_of(i));
        return at_thickness;
      });
    }
    if (stored_film_) {
      return compare_filmed(
          results, [&](std::size_t) -> const runtime::FilmTable& { return *stored_film_; });
    }
    const runtime::Coefficients& c = compiled_.coefficients;
    CheckedQuantity fresnel{"F", tolerance_.fresnel};
    CheckedQuantity preintegrated{"Fbar", tolerance_.preintegrated};
    CheckedQuantity from_embedded{"embedded Fbar", tolerance_.embedded};
    CheckedQuantity closed_form{"closed-form Fbar", tolerance_.analytic};
    for (std::size_t i = 0; i < queries_.size(); ++i) {
      const ValidationQuery& q = queries_[i];
      const float* result = &results[i * kValidationResultsPerQuery * 4];
      record_largest(fresnel, runtime::evaluate_fresnel(c, shader_basis, q.mu), result, i);
      record_largest(preintegrated, runtime::evaluate_fbar(c, table, q.ndotv, q.roughness),
                     result + 4, i);
      if (embedded) {
        record_largest(from_embedded,
                       runtime::evaluate_fbar(c, embedded->view(), q.ndotv, q.roughness),
                       result + 8, i);
      }
      record_largest(closed_form,
                     runtime::evaluate_fbar_analytic(c, analytic, q.ndotv, q.roughness),
                     result + 12, i);
    }
    if (embedded) return {fresnel, preintegrated, from_embedded, closed_form};
    return {fresnel, preintegrated, closed_form};
  }

  std::string describe_query(std::size_t index, std::string_view label) const override {
    const ValidationQuery& q = queries_[index];
    if (stored_stack_) {
      // A thickness per pixel: where along the thickness too.
      const std::string at =
          label == "F" ? fmt::format("mu {:.4f}", q.mu)
                       : fmt::format("NdotV {:.4f}, roughness {:.4f}", q.ndotv, q.roughness);
      return fmt::format("{}, thickness {:.4f}", at, thickness_of(index));
    }
    if (label == "F" || label == "coat F") return fmt::format("mu {:.4f}", q.mu);
    if (label == "F(metal-rough)") {
      return fmt::format("mu {:.4f}, NdotV {:.4f}, metalness {:.4f}", q.mu, q.ndotv, q.roughness);
    }
    if (label == "coat transmission") return fmt::format("NdotV {:.4f}", q.ndotv);
    if (label == "L") {
      return fmt::format("NdotV {:.4f}, roughness {:.4f}, kLayeredValidationQuad", q.ndotv,
                         q.roughness);
    }
    return fmt::format("NdotV {:.4f}, roughness {:.4f}", q.ndotv, q.roughness);
  }

 private:
  // A thickness per pixel's coordinate for query i (0 for other kernels, which ignore it): the
  // golden-ratio sequence, spread over [0, 1] whatever the count, its first at the minimum.
  float thickness_of(std::size_t i) const {
    if (!stored_stack_) return 0.0f;
    const double t = 0.6180339887498949 * static_cast<double>(i);
    return static_cast<float>(t - std::floor(t));
  }

  // A filmed material's F and Fbar, from its table as the file stores it, through the sampler,
  // and kLayeredValidationQuad's light (runtime/ltc.h's film_polygon_light_ltc). `table_at(i)`:
  // the table query i reads (a thickness per pixel's: its stack at the query's thickness, as
  // film_stack_table_at mixes it).
  template <typename TableAt>
  std::vector<CheckedQuantity> compare_filmed(std::span<const float> results,
                                              const TableAt& table_at) const {
    // All through the sampler, whose weights may carry as few as 8 bits.
    CheckedQuantity fresnel{"F", tolerance_.preintegrated};
    CheckedQuantity preintegrated{"Fbar", tolerance_.preintegrated};
    CheckedQuantity quad_light{"L", tolerance_.preintegrated};
    for (std::size_t i = 0; i < queries_.size(); ++i) {
      const ValidationQuery& q = queries_[i];
      const runtime::FilmTable& film = table_at(i);
      const float* result = &results[i * kFilmValidationResultsPerQuery * 4];
      record_largest(fresnel, runtime::film_fresnel(film, q.mu), result, i);
      record_largest(preintegrated, runtime::film_preintegrated(film, q.ndotv, q.roughness),
                     result + 4, i);
      record_largest(quad_light,
                     runtime::film_polygon_light_ltc(film, runtime::shipped_ltc_table(), q.ndotv,
                                                     q.roughness, kLayeredValidationQuad),
                     result + 8, i);
    }
    return {fresnel, preintegrated, quad_light};
  }

  // Both lobes of a layered result: the base's RGB (xyz) into `base`, the coat's F (w) into `coat`.
  static void record_lobes(CheckedQuantity& base, CheckedQuantity& coat,
                           const runtime::CoatedFresnel& expected, const float* actual,
                           std::size_t query) {
    record_largest(base, expected.base, actual, query);
    const float coat_actual[3] = {actual[3], actual[3], actual[3]};
    record_largest(coat, {expected.coat, expected.coat, expected.coat}, coat_actual, query);
  }

  // A layered kernel's glTF metal-rough result (`actual`): the mix under the coat of glTF's
  // dielectric (F0 0.04, F90 1) at mu and the base lobe `base`, metalness = roughness, at NdotV
  // (xyz), and the coat's transmission at NdotV (w).
  void record_metal_rough_under_coat(CheckedQuantity& mix, CheckedQuantity& transmission,
                                     const runtime::ShaderBasis& shader_basis,
                                     const ValidationQuery& q, const runtime::Rgb& base,
                                     const float* actual, std::size_t query) const {
    constexpr runtime::Rgb kGltfDielectric{runtime::kGltfDielectricF0, runtime::kGltfDielectricF0,
                                           runtime::kGltfDielectricF0};
    const double expected =
        runtime::coat_transmission(compiled_.coat->coefficients, shader_basis, q.ndotv);
    record_largest(mix,
                   runtime::metal_rough_under_coat(
                       runtime::dielectric_fresnel(kGltfDielectric, {1.0, 1.0, 1.0}, q.mu), base,
                       q.roughness, expected),
                   actual, query);
    const float transmission_actual[3] = {actual[3], actual[3], actual[3]};
    record_largest(transmission, {expected, expected, expected}, transmission_actual, query);
  }

  // A filmed metal under a coat (runtime/coat.h's evaluate_film_coated_*): the base lobe from its
  // table as the file stores it, the coat lobe from its coefficients and the bound table.
  std::vector<CheckedQuantity> compare_film_coated(std::span<const float> results,
                                                   const runtime::FilmTable& film,
                                                   const runtime::ShaderBasis& shader_basis,
                                                   const runtime::LutView& table) const {
    const runtime::CoatCoefficients& coat = compiled_.coat->coefficients;
    // The base's F comes through the sampler, whose weights may carry as few as 8 bits.
    std::vector<CheckedQuantity> quantities = {
        {"F", tolerance_.preintegrated},          {"coat F", tolerance_.fresnel},
        {"Fbar", tolerance_.preintegrated},       {"coat Fbar", tolerance_.preintegrated},
        {"L", tolerance_.preintegrated},          {"F(metal-rough)", tolerance_.preintegrated},
        {"coat transmission", tolerance_.fresnel}};
    const auto record = [&](std::size_t slot, const runtime::CoatedFresnel& expected,
                            const float* actual, std::size_t query) {
      record_lobes(quantities[2 * slot], quantities[2 * slot + 1], expected, actual, query);
    };
    for (std::size_t i = 0; i < queries_.size(); ++i) {
      const ValidationQuery& q = queries_[i];
      const float* result = &results[i * kFilmCoatedValidationResultsPerQuery * 4];
      const runtime::CoatedFresnel lobes =
          runtime::evaluate_film_coated_fresnel(film, coat, shader_basis, q.mu);
      record(0, lobes, result, i);
      record(1, runtime::evaluate_film_coated_fbar(film, coat, table, q.ndotv, q.roughness),
             result + 4, i);
      record_largest(
          quantities[4],
          runtime::film_polygon_light_ltc_coated(film, coat, table, runtime::shipped_ltc_table(),
                                                 q.ndotv, q.roughness, kLayeredValidationQuad)
              .total(),
          result + 8, i);
      record_metal_rough_under_coat(quantities[5], quantities[6], shader_basis, q, lobes.base,
                                    result + 12, i);
    }
    return quantities;
  }

  // Both lobes of a coated material (runtime/coat.h): the base's RGB and the coat's F, each
  // direct and through the three tables.
  std::vector<CheckedQuantity> compare_coated(
      std::span<const float> results, const runtime::ShaderBasis& shader_basis,
      const runtime::LutView& table, const Lut* embedded,
      const runtime::AnalyticLutCoefficients& analytic) const {
    const runtime::Coefficients& c = compiled_.coefficients;
    const runtime::CoatCoefficients& coat = compiled_.coat->coefficients;
    std::vector<CheckedQuantity> quantities = {{"F", tolerance_.fresnel},
                                               {"coat F", tolerance_.fresnel},
                                               {"Fbar", tolerance_.preintegrated},
                                               {"coat Fbar", tolerance_.preintegrated},
                                               {"embedded Fbar", tolerance_.embedded},
                                               {"embedded coat Fbar", tolerance_.embedded},
                                               {"closed-form Fbar", tolerance_.analytic},
                                               {"closed-form coat Fbar", tolerance_.analytic},
                                               {"L", tolerance_.preintegrated},
                                               {"F(metal-rough)", tolerance_.fresnel},
                                               {"coat transmission", tolerance_.fresnel}};
    const auto record = [&](std::size_t slot, const runtime::CoatedFresnel& expected,
                            const float* actual, std::size_t query) {
      record_lobes(quantities[2 * slot], quantities[2 * slot + 1], expected, actual, query);
    };
    for (std::size_t i = 0; i < queries_.size(); ++i) {
      const ValidationQuery& q = queries_[i];
      const float* result = &results[i * kCoatedValidationResultsPerQuery * 4];
      const runtime::CoatedFresnel lobes =
          runtime::evaluate_coated_fresnel(c, coat, shader_basis, q.mu);
      record(0, lobes, result, i);
      record_largest(quantities[8],
                     runtime::polygon_light_ltc_coated(c, coat, table, runtime::shipped_ltc_table(),
                                                       q.ndotv, q.roughness, kLayeredValidationQuad)
                         .total(),
                     result + 16, i);
      record(1, runtime::evaluate_coated_fbar(c, coat, table, q.ndotv, q.roughness), result + 4, i);
      record_metal_rough_under_coat(quantities[9], quantities[10], shader_basis, q, lobes.base,
                                    result + 20, i);
      if (embedded) {
        record(2, runtime::evaluate_coated_fbar(c, coat, embedded->view(), q.ndotv, q.roughness),
               result + 8, i);
      }
      record(3,
             runtime::evaluate_coated_preintegrated(
                 c, coat, runtime::preintegrated_basis_analytic(analytic, q.ndotv, q.roughness),
                 runtime::preintegrated_basis_analytic(analytic, q.ndotv, coat.roughness), q.ndotv),
             result + 12, i);
    }
    if (!embedded) quantities.erase(quantities.begin() + 4, quantities.begin() + 6);
    return quantities;
  }

  const Build& build_;
  const CompiledMaterial& compiled_;
  ValidationTolerance tolerance_;
  std::vector<ValidationQuery> queries_;
  std::optional<runtime::FilmTable> stored_film_;   // a filmed metal's table as its file holds it
  std::optional<runtime::FilmStack> stored_stack_;  // a thickness per pixel's, as its file holds it
};

}  // namespace

std::vector<ValidationQuery> validation_queries() {
  constexpr std::size_t kCount = (kGridSteps + 1) * (kGridSteps + 1);
  std::vector<ValidationQuery> queries;
  queries.reserve(kCount);
  for (std::size_t row = 0; row <= kGridSteps; ++row) {
    for (std::size_t column = 0; column <= kGridSteps; ++column) {
      const std::size_t index = queries.size();
      queries.push_back({static_cast<float>(static_cast<double>(index) / (kCount - 1)),
                         static_cast<float>(static_cast<double>(column) / kGridSteps),
                         static_cast<float>(static_cast<double>(row) / kGridSteps)});
    }
  }
  return queries;
}

std::unique_ptr<DeviceCheck> material_check(const Build& build, const CompiledMaterial& compiled,
                                            const ValidationTolerance& tolerance) {
  return std::make_unique<MaterialCheck>(build, compiled, tolerance);
}

}  // namespace matc
