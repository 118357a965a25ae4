// The coefficient table of textured metals: its checked-in data, the runtime's reading of it, and
// the accuracy targets of issue #14 against the per-material compile.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "compile/compile.h"
#include "fit/coefficient_table.h"
#include "fit/coefficients.h"
#include "lut/coefficient_table_files.h"
#include "lut/preintegrate.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/shader_basis.h"
#include "optics/gulbrandsen.h"
#include "sanitized_build.h"

namespace {

using matc::runtime::BasisKind;

double channel_f(const matc::runtime::ChannelCoefficients& c, const std::array<double, 4>& b) {
  return std::max(0.0, c[0] * b[0] + c[1] * b[1] + c[2] * b[2] + c[3] * b[3]);
}

// The checked-in tables are what `matc basis coefficient-table` fits today, bit for bit (under
// sanitizers the default basis' alone: the fit's code is the same for every basis).
TEST(CoefficientTable, CheckedInTablesAreCurrent) {
  for (const BasisKind kind : matc::runtime::kShippedBases) {
    if (matc::test::kSanitizedBuild && kind != matc::runtime::kDefaultBasis) continue;
    const matc::CoefficientTable fitted = matc::fit_coefficient_table(kind);
    const matc::runtime::CoefficientTableView shipped =
        matc::runtime::shipped_coefficient_table(kind);
    ASSERT_EQ(shipped.size, fitted.size()) << matc::runtime::basis_name(kind);
    ASSERT_EQ(shipped.texels.size(), fitted.texels.size());
    for (std::size_t i = 0; i < fitted.texels.size(); ++i)
      ASSERT_EQ(shipped.texels[i], fitted.texels[i]) << "texel value " << i;
  }
}

TEST(CoefficientTable, AxesRoundTripAndSpanTheRange) {
  using matc::runtime::coefficient_table_edge_tint_from_v;
  using matc::runtime::coefficient_table_reflectivity_from_u;
  using matc::runtime::coefficient_table_u_from_reflectivity;
  using matc::runtime::coefficient_table_v_from_edge_tint;
  EXPECT_DOUBLE_EQ(coefficient_table_u_from_reflectivity(0.0), 0.0);
  EXPECT_DOUBLE_EQ(coefficient_table_u_from_reflectivity(1.0), 1.0);
  EXPECT_DOUBLE_EQ(coefficient_table_v_from_edge_tint(0.0), 0.0);
  EXPECT_DOUBLE_EQ(coefficient_table_v_from_edge_tint(1.0), 1.0);
  for (const double x : {0.0, 1e-7, 1e-4, 0.01, 0.3, 0.9, 0.999, 1.0}) {
    EXPECT_NEAR(coefficient_table_reflectivity_from_u(coefficient_table_u_from_reflectivity(x)), x,
                1e-12 * std::max(x, 1e-3));
    EXPECT_NEAR(coefficient_table_edge_tint_from_v(coefficient_table_v_from_edge_tint(x)), x,
                1e-12);
  }
  // Texels crowd at both ends of r (the first cell ends below what a 16-bit map holds) and
  // towards g = 1.
  const double last = 1.0 - 1.0 / 127.0;
  EXPECT_LT(coefficient_table_reflectivity_from_u(1.0 / 127.0), 1e-7);
  EXPECT_GT(coefficient_table_reflectivity_from_u(last), 0.99);
  EXPECT_GT(coefficient_table_edge_tint_from_v(last), 0.9999);
}

TEST(CoefficientTable, TexelCentresReadBackAndFullReflectivityIsOne) {
  const auto table = matc::runtime::shipped_coefficient_table();
  const std::size_t x = 40, y = 70;
  const double u = static_cast<double>(x) / static_cast<double>(table.size - 1);
  const double r = matc::runtime::coefficient_table_reflectivity_from_u(u);
  const double g = matc::runtime::coefficient_table_edge_tint_from_v(
      static_cast<double>(y) / static_cast<double>(table.size - 1));
  const auto c = matc::runtime::channel_coefficients_from_table(table, r, g);
  EXPECT_NEAR(c[2], table.texel(x, y)[0], 1e-6);
  EXPECT_NEAR(c[3], table.texel(x, y)[1], 1e-6);
  // r = 1: F = 1 at every angle, whatever the edge tint.
  const auto& shader_basis = matc::runtime::shipped_shader_basis();
  for (const double tint : {0.0, 0.5, 1.0}) {
    const auto one = matc::runtime::channel_coefficients_from_table(table, 1.0, tint);
    for (const double mu : {0.0, 0.3, 1.0})
      EXPECT_NEAR(channel_f(one, matc::runtime::evaluate_shader_basis(shader_basis, mu)), 1.0,
                  1e-12);
  }
}

TEST(CoefficientTable, ArtisticFromIorInvertsGulbrandsen) {
  for (const double r : {0.05, 0.4, 0.9})
    for (const double g : {0.0, 0.3, 1.0}) {
      const matc::ComplexIor ior = matc::gulbrandsen_to_ior({r, g});
      const auto artistic = matc::runtime::artistic_from_ior({ior.n, 1.0, 1.0}, {ior.k, 0.0, 0.0});
      EXPECT_NEAR(artistic.reflectivity[0], r, 1e-12);
      EXPECT_NEAR(artistic.edge_tint[0], g, 1e-9);
    }
  // Outside the artistic range (n below n_min(r)) the edge tint is clamped to 1.
  const auto beyond = matc::runtime::artistic_from_ior({0.01, 0.01, 0.01}, {0.3, 0.3, 0.3});
  EXPECT_EQ(beyond.edge_tint[0], 1.0);
}

TEST(CoefficientTable, F16StorageRoundsThroughHalf) {
  const matc::CoefficientTable table =
      matc::stored_coefficient_table(BasisKind::extended, matc::LutPrecision::f32);
  const matc::CoefficientTable half = matc::stored_as(table, matc::LutPrecision::f16);
  EXPECT_EQ(matc::stored_coefficient_table(BasisKind::extended, matc::LutPrecision::f16).texels,
            half.texels);
  double worst = 0.0;
  for (std::size_t i = 0; i < table.texels.size(); ++i)
    worst = std::max(worst, std::abs(static_cast<double>(half.texels[i] - table.texels[i])));
  EXPECT_GT(worst, 0.0);
  EXPECT_LT(worst, 2e-3);
}

// Issue #14's targets over 2,000 random (r, g), r <= 0.95, and near-black metals (r down to 1e-5):
// where the per-material compile fits (within 0.05 of the exact curve) the table path stays within
// 0.002 of it and within 2e-4 on average; where the compile does not fit, the table is at most
// 0.002 further from the exact curve. The same for Fbar through the 128² table. Near-black metals
// get 0.005 (curves change fastest with r there: docs/accuracy.md).
TEST(CoefficientTable, MeetsTheTargetsAgainstThePerMaterialCompile) {
  const auto table = matc::runtime::shipped_coefficient_table();
  const auto basis = matc::runtime::shipped_basis();
  const auto& shader_basis = matc::runtime::shipped_shader_basis();
  const matc::Lut lut = matc::preintegrate_lut(basis, {128, 256});
  std::mt19937_64 generator(1414);
  const auto unit = [&] { return static_cast<double>(generator() >> 11) * 0x1.0p-53; };
  std::vector<std::array<double, 4>> b(401);
  for (std::size_t j = 0; j < b.size(); ++j)
    b[j] = matc::runtime::evaluate_shader_basis(shader_basis, static_cast<double>(j) / 400.0);
  // Index 0: the 2,000 draws over the range; 1: the near-black ones.
  std::array<double, 2> worst{}, worst_fbar{}, worst_excess{};
  double sum = 0.0;
  std::size_t count = 0;
  for (int i = 0; i < 2200; ++i) {
    // 2,000 draws over the range, then 200 near-black ones (r log-uniform in [1e-5, 0.002]).
    const double r = i < 2000 ? 0.95 * unit() : 1e-5 * std::pow(200.0, unit());
    const double g = unit();
    const std::size_t set = i < 2000 ? 0 : 1;
    const matc::ComplexIor ior = matc::gulbrandsen_to_ior({r, g});
    const matc::IorCurve curve({ior, ior, ior});
    const auto compiled = matc::solve_coefficients(curve, basis)[0];
    const auto from_table = matc::runtime::channel_coefficients_from_table(table, r, g);
    double compile_error = 0.0, table_error = 0.0, difference = 0.0;
    for (std::size_t j = 0; j < b.size(); ++j) {
      const double exact = matc::fresnel_exact(static_cast<double>(j) / 400.0, ior);
      const double f_table = channel_f(from_table, b[j]);
      const double f_compiled = channel_f(compiled, b[j]);
      compile_error = std::max(compile_error, std::abs(f_compiled - exact));
      table_error = std::max(table_error, std::abs(f_table - exact));
      difference = std::max(difference, std::abs(f_table - f_compiled));
      sum += std::abs(f_table - f_compiled);
      ++count;
    }
    if (compile_error > matc::kPoorFitMaxError) {
      worst_excess[set] = std::max(worst_excess[set], table_error - compile_error);
      continue;
    }
    worst[set] = std::max(worst[set], difference);
    for (int a = 0; a <= 8; ++a)
      for (int c = 0; c <= 8; ++c) {
        const auto bbar = matc::runtime::sample_lut(lut.view(), a / 8.0, c / 8.0);
        worst_fbar[set] = std::max(
            worst_fbar[set], std::abs(channel_f(from_table, bbar) - channel_f(compiled, bbar)));
      }
  }
  EXPECT_LE(worst[0], 0.002);
  EXPECT_LE(sum / static_cast<double>(count), 2e-4);
  EXPECT_LE(worst_fbar[0], 0.002);
  EXPECT_LE(worst_excess[0], 0.002);
  EXPECT_LE(worst[1], 0.005);
  EXPECT_LE(worst_fbar[1], 0.005);
  EXPECT_LE(worst_excess[1], 0.005);
}

}  // namespace
