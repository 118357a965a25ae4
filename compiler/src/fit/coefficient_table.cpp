#include "fit/coefficient_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "base/parallel_rows.h"
#include "fit/coefficients.h"
#include "formats/header_arrays.h"
#include "matc/runtime/shader_basis.h"
#include "matc/version.h"
#include "optics/gulbrandsen.h"
#include "optics/reflectance_curve.h"

namespace matc {
namespace {

// delta = 1 - n_min(r) / n_max(r) = 2 sqrt(r) / (1 + r): 0 at r = 0, 1 at r = 1 (the log n and
// 1/n rows).
double ior_span(double reflectivity) {
  const double r = std::clamp(reflectivity, 0.0, 1.0);
  return 2.0 * std::sqrt(r) / (1.0 + r);
}

// v = log(1 - g delta) / log(1 - delta), v = g as delta -> 0, and back.
double log_ior_v(double reflectivity, double g) {
  const double delta = ior_span(reflectivity);
  if (delta <= 0.0) return g;                    // r = 0: n_min = n_max = 1
  if (delta >= 1.0) return g < 1.0 ? 0.0 : 1.0;  // r = 1: n_max is infinite
  return std::log1p(-g * delta) / std::log1p(-delta);
}

double log_ior_edge_tint(double reflectivity, double v) {
  const double delta = ior_span(reflectivity);
  if (delta <= 0.0 || delta >= 1.0) return v;
  return -std::expm1(v * std::log1p(-delta)) / delta;
}

double u_coordinate(const CoefficientTableOptions& options, double reflectivity) {
  switch (options.axis) {
    case ReflectivityAxis::fourth_root_plus_square:
      return runtime::coefficient_table_u_from_reflectivity(reflectivity);
    case ReflectivityAxis::cube_root:
      return std::cbrt(std::clamp(reflectivity, 0.0, 1.0));
    case ReflectivityAxis::square_root:
      return std::sqrt(std::clamp(reflectivity, 0.0, 1.0));
    case ReflectivityAxis::fourth_root:
      return std::sqrt(std::sqrt(std::clamp(reflectivity, 0.0, 1.0)));
    case ReflectivityAxis::stretched_square_root: {
      const double s = std::sqrt(std::clamp(reflectivity, 0.0, 1.0));
      return 2.0 * s / (1.0 + s);
    }
    case ReflectivityAxis::linear:
      break;
  }
  return std::clamp(reflectivity, 0.0, 1.0);
}

double v_coordinate(const CoefficientTableOptions& options, double reflectivity, double edge_tint) {
  const double g = std::clamp(edge_tint, 0.0, 1.0);
  switch (options.edge_tint_axis) {
    case EdgeTintAxis::log_ior:
      return log_ior_v(reflectivity, g);
    case EdgeTintAxis::inverse_ior: {
      const double delta = ior_span(reflectivity);
      return delta >= 1.0 ? (g < 1.0 ? 0.0 : 1.0) : g * (1.0 - delta) / (1.0 - g * delta);
    }
    case EdgeTintAxis::complement_square_root:
      return runtime::coefficient_table_v_from_edge_tint(g);
    case EdgeTintAxis::complement_fourth_root:
      return 1.0 - std::sqrt(std::sqrt(1.0 - g));
    case EdgeTintAxis::complement_eighth_root:
      return 1.0 - std::sqrt(std::sqrt(std::sqrt(1.0 - g)));
    case EdgeTintAxis::linear:
      break;
  }
  return g;
}

runtime::Coefficients solve(const ReflectanceCurve& curve, runtime::BasisKind basis,
                            TableSolve method) {
  if (method == TableSolve::least_squares) {
    return solve_coefficients_least_squares(curve, runtime::shipped_shader_basis(basis));
  }
  return solve_coefficients(curve, runtime::shipped_basis(basis));
}

// Solves the texels of one row, three columns at a time (one per colour channel of an IorCurve).
void fit_row(CoefficientTable& table, std::size_t y) {
  const std::size_t size = table.size();
  for (std::size_t x0 = 0; x0 < size; x0 += 3) {
    std::array<ComplexIor, 3> ior{};
    std::array<double, 3> solved_r{};
    for (std::size_t c = 0; c < 3; ++c) {
      const std::size_t x = std::min(x0 + c, size - 1);
      const double column = x == 0 ? table.options.first_column_offset : static_cast<double>(x);
      solved_r[c] = coefficient_table_column_reflectivity(table.options, column);
      const double g = coefficient_table_row_edge_tint(table.options, solved_r[c], y);
      // The last column (r = 1, F = 1 at every angle) is not solved: it stays zero. Its slot in
      // the batch gets a harmless placeholder.
      ior[c] = x < size - 1 ? gulbrandsen_to_ior({solved_r[c], g}) : ComplexIor{1.5, 0.0};
    }
    const runtime::Coefficients coefficients =
        solve(IorCurve(ior), table.basis, table.options.solve);
    for (std::size_t c = 0; c < 3 && x0 + c < size - 1; ++c) {
      const double scale =
          table.options.values == TableValues::normalised ? 1.0 / (1.0 - solved_r[c]) : 1.0;
      const std::size_t offset = (y * size + x0 + c) * runtime::kCoefficientTableChannels;
      table.texels[offset] = static_cast<float>(coefficients[c][2] * scale);
      table.texels[offset + 1] = static_cast<float>(coefficients[c][3] * scale);
    }
  }
}

}  // namespace

bool CoefficientTable::shipped_layout() const {
  return options.axis == ReflectivityAxis::fourth_root_plus_square &&
         options.edge_tint_axis == EdgeTintAxis::complement_square_root &&
         options.values == TableValues::raw;
}

runtime::CoefficientTableView CoefficientTable::view() const {
  if (!shipped_layout()) throw std::logic_error("only the shipped table layout has a runtime view");
  return {options.size, texels};
}

double coefficient_table_column_reflectivity(const CoefficientTableOptions& options, double x) {
  const double u = x / static_cast<double>(options.size - 1);
  switch (options.axis) {
    case ReflectivityAxis::fourth_root_plus_square:
      return runtime::coefficient_table_reflectivity_from_u(u);
    case ReflectivityAxis::cube_root:
      return u * u * u;
    case ReflectivityAxis::square_root:
      return u * u;
    case ReflectivityAxis::fourth_root:
      return u * u * u * u;
    case ReflectivityAxis::stretched_square_root: {
      const double s = u / (2.0 - u);
      return s * s;
    }
    case ReflectivityAxis::linear:
      break;
  }
  return u;
}

double coefficient_table_row_edge_tint(const CoefficientTableOptions& options, double reflectivity,
                                       std::size_t y) {
  const double v = static_cast<double>(y) / static_cast<double>(options.size - 1);
  switch (options.edge_tint_axis) {
    case EdgeTintAxis::log_ior:
      return std::clamp(log_ior_edge_tint(reflectivity, v), 0.0, 1.0);
    case EdgeTintAxis::inverse_ior: {
      // v = g (1 - delta) / (1 - g delta)  <=>  g = v / (1 - delta + v delta).
      const double delta = ior_span(reflectivity);
      return std::clamp(v / (1.0 - delta + v * delta), 0.0, 1.0);
    }
    case EdgeTintAxis::complement_square_root:
      return runtime::coefficient_table_edge_tint_from_v(v);
    case EdgeTintAxis::complement_fourth_root:
      return 1.0 - std::pow(1.0 - v, 4.0);
    case EdgeTintAxis::complement_eighth_root:
      return 1.0 - std::pow(1.0 - v, 8.0);
    case EdgeTintAxis::linear:
      break;
  }
  return v;
}

CoefficientTable fit_coefficient_table(runtime::BasisKind basis,
                                       const CoefficientTableOptions& options) {
  if (options.size < kMinCoefficientTableSize || options.size > kMaxCoefficientTableSize) {
    throw std::invalid_argument(fmt::format("coefficient table size {} outside [{}, {}]",
                                            options.size, kMinCoefficientTableSize,
                                            kMaxCoefficientTableSize));
  }
  CoefficientTable table{options, basis, {}};
  table.texels.assign(options.size * options.size * runtime::kCoefficientTableChannels, 0.0f);
  fill_rows_in_parallel(options.size, options.threads,
                        [&] { return [&](std::size_t y) { fit_row(table, y); }; });
  return table;
}

std::vector<float> rgba_texels(const CoefficientTable& table) {
  std::vector<float> texels(table.size() * table.size() * 4, 0.0f);
  for (std::size_t i = 0; i < table.size() * table.size(); ++i) {
    texels[4 * i] = table.texels[2 * i];
    texels[4 * i + 1] = table.texels[2 * i + 1];
  }
  return texels;
}

runtime::ChannelCoefficients channel_coefficients(const CoefficientTable& table,
                                                  double reflectivity, double edge_tint) {
  if (table.shipped_layout()) {
    return runtime::channel_coefficients_from_table(table.view(), reflectivity, edge_tint);
  }
  // The same bilinear read at this layout's coordinates.
  const double r = std::clamp(reflectivity, 0.0, 1.0);
  const auto sampled = runtime::sample_coefficient_table_at(
      {table.size(), table.texels}, u_coordinate(table.options, r),
      v_coordinate(table.options, r, edge_tint));
  const double scale = table.options.values == TableValues::normalised ? 1.0 - r : 1.0;
  return {r, 1.0 - r, scale * sampled[0], scale * sampled[1]};
}

std::string coefficient_table_source(const CoefficientTable& table) {
  const std::string name(runtime::basis_name(table.basis));
  std::string out = fmt::format(
      "// Generated by `matc basis coefficient-table --basis {}` (matc {}). Do not edit: rerun\n"
      "// it. (c_2, c_3) of Gulbrandsen conductors, {} x {} texels: columns (r^(1/4) + r^2) / 2 =\n"
      "// x / {}, rows 1 - sqrt(1 - g) = y / {} (layout: matc/runtime/coefficient_table.h), each\n"
      "// texel the basis' own coefficient solve; the last column (r = 1) is zero.\n"
      "// clang-format off\n"
      "#include \"matc/runtime/coefficient_table.h\"\n\n"
      "namespace matc::runtime {{\n"
      "namespace {{\n\n"
      "constexpr std::size_t kSize = {};\n",
      name, kVersion, table.size(), table.size(), table.size() - 1, table.size() - 1, table.size());
  formats::append_float_array(out, "constexpr", "kTexels", table.texels, 8);
  out += fmt::format(
      "}}  // namespace\n\n"
      "CoefficientTableView {}_coefficient_table() {{\n"
      "  return {{kSize, kTexels}};\n"
      "}}\n\n"
      "}}  // namespace matc::runtime\n",
      name);
  return out;
}

}  // namespace matc
