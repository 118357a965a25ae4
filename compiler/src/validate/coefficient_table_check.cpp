// The coefficient-table check: the textured-metal paths (the coefficient table from (r, g) and
// from (n, k), and the baked coefficient textures' function) against the CPU runtime.
#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/format.h>

#include "emit/validation_kernel.h"
#include "largest_difference.h"
#include "matc/runtime/baked_coefficients.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/f0_table.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/metal_rough.h"
#include "matc/runtime/shader_basis.h"
#include "validate/device_validator.h"

namespace matc {
namespace {

constexpr std::size_t kTableQueries = 4096;

runtime::Rgb as_rgb(const std::array<float, 3>& values) {
  return {values[0], values[1], values[2]};
}

// The kernels' F0 table for a query (matc_check_f0_entry in templates/*/validate_table.*): entry
// i of channel c from the query's g, n, k, not linear in i, the same in air and under the coat.
runtime::F0Table query_f0_table(const TableQuery& q) {
  runtime::F0Table table;
  for (std::size_t i = 0; i < runtime::kF0TableEntries; ++i) {
    const float s = static_cast<float>(i * i) / 1024.0f;
    for (std::size_t c = 0; c < 3; ++c) {
      const float g = q.edge_tint[c], n = q.n[c], k = q.k[c] * 0.125f;
      table.in_air[i][c] = {g + s * n * 0.25f, k + s * (0.5f - g), (g - 0.5f) + s * (1.0f - g),
                            (k - 0.5f) + s * (k - 0.25f)};
    }
  }
  table.under_coat = table.in_air;
  return table;
}

class CoefficientTableCheck final : public DeviceCheck {
 public:
  CoefficientTableCheck(const Build& build, const ValidationTolerance& tolerance)
      : build_(build), tolerance_(tolerance.preintegrated), queries_(table_validation_queries()) {}

  std::string subject() const override { return "coefficient table"; }
  SpirvWords kernel(ShaderLanguage language) const override {
    return table_validation_module(build_, language);
  }
  KernelTables tables() const override { return {true, false, {}}; }
  std::size_t query_count() const override { return queries_.size(); }

  std::vector<float> packed_queries() const override {
    std::vector<float> packed;
    packed.reserve(queries_.size() * kTableValidationQueryVectors * 4);
    for (const TableQuery& q : queries_) {
      packed.insert(packed.end(), {q.reflectivity[0], q.reflectivity[1], q.reflectivity[2], q.mu});
      packed.insert(packed.end(), {q.edge_tint[0], q.edge_tint[1], q.edge_tint[2], q.ndotv});
      packed.insert(packed.end(), {q.n[0], q.n[1], q.n[2], q.roughness});
      packed.insert(packed.end(), {q.k[0], q.k[1], q.k[2], 0.0f});
    }
    return packed;
  }

  std::size_t result_vec4s_per_query() const override { return kTableValidationResultsPerQuery; }

  std::vector<CheckedQuantity> compare(std::span<const float> results) const override {
    const runtime::ShaderBasis& shader_basis =
        runtime::shipped_shader_basis(build_.options().basis);
    const runtime::CoefficientTableView table = build_.stored_coefficient_table().view();
    const runtime::LutView lut = build_.stored_lut().view();
    // Every result goes through a sampler: the preintegrated tolerance for all.
    CheckedQuantity fresnel{"F(r, g)", tolerance_};
    CheckedQuantity preintegrated{"Fbar(r, g)", tolerance_};
    CheckedQuantity from_ior{"F(n, k)", tolerance_};
    CheckedQuantity baked{"F(baked)", tolerance_};
    CheckedQuantity from_f0{"F(from F0)", tolerance_};
    CheckedQuantity f0_table{"F(F0 table)", tolerance_};
    CheckedQuantity f0_table_under_coat{"F(F0 table, under a coat)", tolerance_};
    CheckedQuantity metal_rough{"F(metal-rough)", tolerance_};
    for (std::size_t i = 0; i < queries_.size(); ++i) {
      const TableQuery& q = queries_[i];
      const float* result = &results[i * kTableValidationResultsPerQuery * 4];
      const runtime::Coefficients coefficients =
          runtime::coefficients_from_table(table, as_rgb(q.reflectivity), as_rgb(q.edge_tint));
      record_largest(fresnel, runtime::evaluate_fresnel(coefficients, shader_basis, q.mu), result,
                     i);
      record_largest(preintegrated, runtime::evaluate_fbar(coefficients, lut, q.ndotv, q.roughness),
                     result + 4, i);
      const runtime::ArtisticRgb artistic = runtime::artistic_from_ior(as_rgb(q.n), as_rgb(q.k));
      const runtime::Coefficients ior_coefficients =
          runtime::coefficients_from_table(table, artistic.reflectivity, artistic.edge_tint);
      record_largest(from_ior, runtime::evaluate_fresnel(ior_coefficients, shader_basis, q.mu),
                     result + 8, i);
      // Baked texels of either sign: the query's r as F0, g - 0.5 as c_2 and k / 8 - 0.5 as c_3.
      runtime::Rgb c2{}, c3{};
      for (std::size_t c = 0; c < 3; ++c) {
        c2[c] = static_cast<double>(q.edge_tint[c] - 0.5f);
        c3[c] = static_cast<double>(q.k[c] * 0.125f - 0.5f);
      }
      const runtime::Coefficients baked_coefficients =
          runtime::coefficients_from_baked(as_rgb(q.reflectivity), c2, c3);
      record_largest(baked, runtime::evaluate_fresnel(baked_coefficients, shader_basis, q.mu),
                     result + 12, i);
      // Per pixel from F0 = r, on those rows taken at F0 = 0.
      const runtime::Coefficients per_pixel = runtime::coefficients_from_f0(
          runtime::coefficients_from_baked({0.0, 0.0, 0.0}, c2, c3), as_rgb(q.reflectivity));
      record_largest(from_f0, runtime::evaluate_fresnel(per_pixel, shader_basis, q.mu), result + 16,
                     i);
      // Per pixel from F0 = r through an F0 table of the query's values.
      const runtime::F0Table table_of_query = query_f0_table(q);
      record_largest(f0_table,
                     runtime::evaluate_fresnel(runtime::coefficients_from_f0_table(
                                                   table_of_query, as_rgb(q.reflectivity)),
                                               shader_basis, q.mu),
                     result + 20, i);
      record_largest(f0_table_under_coat,
                     runtime::evaluate_fresnel(runtime::under_coat_coefficients_from_f0_table(
                                                   table_of_query, as_rgb(q.reflectivity)),
                                               shader_basis, q.mu),
                     result + 24, i);
      // glTF's metal-rough mix: the (r, g) metal with a dielectric of F0 g * 0.08 and F90 NdotV,
      // by metalness = roughness.
      const runtime::Rgb dielectric = runtime::dielectric_fresnel(
          as_rgb({q.edge_tint[0] * 0.08f, q.edge_tint[1] * 0.08f, q.edge_tint[2] * 0.08f}),
          {q.ndotv, q.ndotv, q.ndotv}, q.mu);
      record_largest(
          metal_rough,
          runtime::metal_rough(
              dielectric, runtime::evaluate_fresnel(coefficients, shader_basis, q.mu), q.roughness),
          result + 28, i);
    }
    return {fresnel,  preintegrated,       from_ior,   baked, from_f0,
            f0_table, f0_table_under_coat, metal_rough};
  }

  std::string describe_query(std::size_t index, std::string_view label) const override {
    const TableQuery& q = queries_[index];
    const bool ior = label == "F(n, k)";
    const auto& first = ior ? q.n : q.reflectivity;
    const auto& second = ior ? q.k : q.edge_tint;
    return fmt::format(
        "{} ({:.4f}, {:.4f}, {:.4f}), {} ({:.4f}, {:.4f}, {:.4f}), mu {:.4f}, NdotV {:.4f}, "
        "roughness {:.4f}",
        ior ? "n" : "r", first[0], first[1], first[2], ior ? "k" : "g", second[0], second[1],
        second[2], q.mu, q.ndotv, q.roughness);
  }

 private:
  const Build& build_;
  double tolerance_;
  std::vector<TableQuery> queries_;
};

}  // namespace

std::vector<TableQuery> table_validation_queries() {
  // Fixed-seed draws (mt19937_64's output is specified by the standard), with every eighth query
  // on the table's edges: r and g of 0 or 1 in some channel.
  std::mt19937_64 generator(14);
  const auto unit = [&] {
    return static_cast<float>(static_cast<double>(generator() >> 40) * 0x1.0p-24);
  };
  std::vector<TableQuery> queries(kTableQueries);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    TableQuery& q = queries[i];
    for (std::size_t c = 0; c < 3; ++c) {
      q.reflectivity[c] = unit();
      q.edge_tint[c] = unit();
      q.n[c] = 0.05f * std::pow(80.0f, unit());
      q.k[c] = 8.0f * unit();
    }
    if (i % 8 == 0) {
      q.reflectivity[i / 8 % 3] = static_cast<float>(i / 24 % 2);
      q.edge_tint[(i / 8 + 1) % 3] = static_cast<float>(i / 48 % 2);
    }
    q.mu = unit();
    q.ndotv = unit();
    q.roughness = unit();
  }
  return queries;
}

std::unique_ptr<DeviceCheck> coefficient_table_check(const Build& build,
                                                     const ValidationTolerance& tolerance) {
  return std::make_unique<CoefficientTableCheck>(build, tolerance);
}

}  // namespace matc
