// DeviceValidator::validate_coefficient_table: the textured-metal paths (the coefficient table,
// and the baked coefficient textures' function), run from GLSL and HLSL.
#include <algorithm>
#include <cmath>
#include <random>

#include "matc/emit/validation_kernel.h"
#include "matc/runtime/baked_coefficients.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/shader_basis.h"
#include "matc/validate/device_validation.h"
#include "matc/vulkan/compute_kernel.h"
#include "validator_device.h"

namespace matc {
namespace {

constexpr std::size_t kTableQueries = 4096;

void record(TableDiscrepancy& discrepancy, const runtime::Rgb& expected, const float* actual,
            std::size_t query) {
  record_largest(discrepancy.max_abs, discrepancy.query, expected, actual, query);
}

runtime::Rgb as_rgb(const std::array<float, 3>& values) {
  return {values[0], values[1], values[2]};
}

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

bool TableValidation::passed() const {
  return !paths.empty() && std::all_of(paths.begin(), paths.end(),
                                       [](const TablePathValidation& p) { return p.passed; });
}

TableValidation DeviceValidator::validate_coefficient_table() const {
  TableValidation validation;
  for (const ShaderLanguage language : {ShaderLanguage::glsl, ShaderLanguage::hlsl})
    validation.paths.push_back(run_table(language));
  return validation;
}

TablePathValidation DeviceValidator::run_table(ShaderLanguage language) const {
  const std::vector<TableQuery> queries = table_validation_queries();
  std::vector<float> packed;
  packed.reserve(queries.size() * kTableValidationQueryVectors * 4);
  for (const TableQuery& q : queries) {
    packed.insert(packed.end(), {q.reflectivity[0], q.reflectivity[1], q.reflectivity[2], q.mu});
    packed.insert(packed.end(), {q.edge_tint[0], q.edge_tint[1], q.edge_tint[2], q.ndotv});
    packed.insert(packed.end(), {q.n[0], q.n[1], q.n[2], q.roughness});
    packed.insert(packed.end(), {q.k[0], q.k[1], q.k[2], 0.0f});
  }
  static_assert(kTableQueries % kWorkgroupSize == 0, "whole workgroups");
  const std::vector<float> results = device_->run_queries(
      build_.table_validation_module(language), packed, queries.size(),
      queries.size() * kTableValidationResultsPerQuery * 4, /*with_ltc=*/false);

  const runtime::ShaderBasis& shader_basis = runtime::shipped_shader_basis(build_.options().basis);
  const runtime::CoefficientTableView table = build_.stored_coefficient_table().view();
  const runtime::LutView lut = build_.stored_lut().view();
  TablePathValidation path;
  path.language = language;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const TableQuery& q = queries[i];
    const float* result = &results[i * kTableValidationResultsPerQuery * 4];
    const runtime::Coefficients coefficients =
        runtime::coefficients_from_table(table, as_rgb(q.reflectivity), as_rgb(q.edge_tint));
    record(path.fresnel, runtime::evaluate_fresnel(coefficients, shader_basis, q.mu), result, i);
    record(path.preintegrated, runtime::evaluate_fbar(coefficients, lut, q.ndotv, q.roughness),
           result + 4, i);
    const runtime::ArtisticRgb artistic = runtime::artistic_from_ior(as_rgb(q.n), as_rgb(q.k));
    const runtime::Coefficients from_ior =
        runtime::coefficients_from_table(table, artistic.reflectivity, artistic.edge_tint);
    record(path.from_ior, runtime::evaluate_fresnel(from_ior, shader_basis, q.mu), result + 8, i);
    runtime::Rgb c2{}, c3{};
    for (std::size_t c = 0; c < 3; ++c) {
      c2[c] = static_cast<double>(q.edge_tint[c] - 0.5f);
      c3[c] = static_cast<double>(q.k[c] * 0.125f - 0.5f);
    }
    const runtime::Coefficients baked =
        runtime::coefficients_from_baked(as_rgb(q.reflectivity), c2, c3);
    record(path.baked, runtime::evaluate_fresnel(baked, shader_basis, q.mu), result + 12, i);
  }
  const double tolerance = tolerance_.preintegrated;
  path.passed = path.fresnel.max_abs <= tolerance && path.preintegrated.max_abs <= tolerance &&
                path.from_ior.max_abs <= tolerance && path.baked.max_abs <= tolerance;
  return path;
}

}  // namespace matc
