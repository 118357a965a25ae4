// The shipped basis: its construction's properties, and that `matc basis fit` reproduces it.
#include <algorithm>
#include <cmath>
#include <utility>

#include <gtest/gtest.h>

#include "basis/basis_fit.h"
#include "basis/basis_polynomial_fit.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/powers_basis.h"
#include "matc/runtime/shader_basis.h"
#include "sanitized_build.h"

namespace matc {
namespace {

using runtime::BasisView;

double max_abs(std::span<const double> values) {
  double peak = 0.0;
  for (const double v : values)
    peak = std::max(peak, std::abs(v));
  return peak;
}

TEST(PaperBasis, HasOneThousandSamplesOverTheUnitInterval) {
  const BasisView basis = runtime::paper_basis();
  EXPECT_EQ(basis.samples(), 1000u);
  EXPECT_EQ(basis.mu_at(0), 0.0);
  EXPECT_EQ(basis.mu_at(999), 1.0);
}

TEST(PaperBasis, FirstElementIsConstantOne) {
  const BasisView basis = runtime::paper_basis();
  for (const double mu : {0.0, 0.3, 0.77, 1.0})
    EXPECT_EQ(basis.evaluate(mu)[0], 1.0);
}

class ShippedBasis : public testing::TestWithParam<runtime::BasisKind> {};
// The bases with checked-in tables and piecewise polynomials (not the closed-form powers basis).
class FittedShippedBasis : public testing::TestWithParam<runtime::BasisKind> {};

TEST_P(ShippedBasis, SecondElementRunsFromOneAtGrazingToZeroAtNormal) {
  const BasisView basis = runtime::shipped_basis(GetParam());
  const auto b1 = basis.tables[0];
  EXPECT_EQ(b1.front(), 1.0);
  EXPECT_EQ(max_abs(b1), 1.0);
  EXPECT_LT(std::abs(b1.back()), 1e-12);
  EXPECT_TRUE(std::is_sorted(b1.rbegin(), b1.rend())) << "b_1 decreases with mu";
}

TEST_P(ShippedBasis, ResidualElementsAreUnitPeakedAndVanishAtTheEnds) {
  const BasisView basis = runtime::shipped_basis(GetParam());
  // The fitted tables are scaled to 1 at a sample; the closed forms are unscaled and their peaks
  // (mu = 1/4, 1/10 for powers, 1/7, 1/12 for f82) fall between samples.
  std::array<double, 2> peaks = {1.0, 1.0};
  if (GetParam() == runtime::BasisKind::powers)
    peaks = {runtime::kPowersB2Peak, runtime::kPowersB3Peak};
  if (GetParam() == runtime::BasisKind::f82) peaks = {runtime::kF82B2Peak, runtime::kF82B3Peak};
  const double tolerance = runtime::is_closed_form(GetParam()) ? 1e-6 : 0.0;
  for (std::size_t i = 1; i < 3; ++i) {
    const auto b = basis.tables[i];
    EXPECT_NEAR(*std::max_element(b.begin(), b.end()), peaks[i - 1], tolerance) << "b_" << i + 1;
    EXPECT_NEAR(max_abs(b), peaks[i - 1], tolerance) << "b_" << i + 1;
    // F(mu = 0) = c0 + c1 and F(1) = c0 rely on these vanishing.
    EXPECT_LT(std::abs(b.front()), 1e-9) << "b_" << i + 1;
    EXPECT_LT(std::abs(b.back()), 1e-9) << "b_" << i + 1;
  }
}

TEST(PaperBasis, ProbesSitWhereTheAuthorsNotebookPutsThem) {
  const BasisView basis = runtime::paper_basis();
  const auto b2 = basis.tables[1];
  const auto b3 = basis.tables[2];
  // mu_1 = argmax b_2: about 0.128 (theta 1.44 rad).
  EXPECT_EQ(basis.probe_indices[0],
            static_cast<std::size_t>(std::max_element(b2.begin(), b2.end()) - b2.begin()));
  EXPECT_NEAR(std::acos(basis.probe_mu(0)), 1.44, 0.01);
  // mu_2 = an extremum of b_3: about 0.432 (theta 1.12 rad).
  const std::size_t p = basis.probe_indices[1];
  const bool is_max = b3[p] >= b3[p - 1] && b3[p] >= b3[p + 1];
  const bool is_min = b3[p] <= b3[p - 1] && b3[p] <= b3[p + 1];
  EXPECT_TRUE(is_max || is_min);
  EXPECT_NEAR(std::acos(basis.probe_mu(1)), 1.12, 0.015);
}

TEST(PaperBasis, InterpolationIsExactAtGridPointsAndLinearBetween) {
  const BasisView basis = runtime::paper_basis();
  const auto at = basis.at_index(500);
  const auto evaluated = basis.evaluate(basis.mu_at(500));
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_NEAR(evaluated[i], at[i], 1e-15);
  const double halfway = 0.5 * (basis.mu_at(10) + basis.mu_at(11));
  EXPECT_NEAR(basis.evaluate(halfway)[2], 0.5 * (basis.tables[1][10] + basis.tables[1][11]), 1e-15);
  EXPECT_EQ(basis.evaluate(-1.0), basis.at_index(0));
  EXPECT_EQ(basis.evaluate(2.0), basis.at_index(999));
}

TEST_P(FittedShippedBasis, RegenerationReproducesTheCheckedInTable) {
  // Under sanitizers one basis' refit stands for the others: the fit's code is the same.
  if (test::kSanitizedBuild && GetParam() != runtime::kFittedBases.front())
    GTEST_SKIP() << "sanitized build: the first fitted basis' regeneration only";
  const FittedBasis fitted = fit_shipped_basis(GetParam());
  const BasisView shipped = runtime::shipped_basis(GetParam());
  EXPECT_EQ(fitted.kind, shipped.kind);
  ASSERT_EQ(fitted.view().samples(), shipped.samples());
  EXPECT_EQ(fitted.probe_indices, shipped.probe_indices);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < shipped.samples(); ++j) {
      ASSERT_NEAR(fitted.tables[i][j], shipped.tables[i][j], 1e-10)
          << "b_" << i + 1 << " at sample " << j << ": rerun `matc basis fit --basis "
          << runtime::basis_name(GetParam()) << " -o runtime/src/generated/"
          << runtime::basis_name(GetParam()) << "_basis_table.cpp`";
    }
  }
  // The polynomial is refitted from the refitted tables; a float ulp of drift is tolerated.
  const runtime::BasisPolynomial& shipped_polynomial =
      runtime::shipped_shader_basis(GetParam()).polynomial;
  for (std::size_t s = 0; s < runtime::kPolynomialSegments; ++s) {
    for (std::size_t p = 0; p <= runtime::kPolynomialDegree; ++p) {
      for (std::size_t i = 0; i < 3; ++i) {
        const double shipped_value = shipped_polynomial[s][p][i];
        ASSERT_NEAR(fitted.shader.polynomial[s][p][i], shipped_value,
                    1e-7 * std::abs(shipped_value) + 1e-12)
            << "segment " << s << ", t^" << runtime::kPolynomialDegree - p << ", b_" << i + 1;
      }
    }
  }
}

// The bound for the shaders' basis: within 1e-4 of the shipped table where the table holds
// data. Between samples the table is a linear interpolation, itself ~1.7e-4 off the smooth curve
// for b_3 near grazing (where it bends fastest, measured with higher-degree fits), so the two may
// differ by up to 3e-4 there.
TEST_P(FittedShippedBasis, PolynomialMatchesTheTableWithin1e4) {
  const PolynomialFitError error = polynomial_fit_error(
      runtime::shipped_shader_basis(GetParam()).polynomial, runtime::shipped_basis(GetParam()));
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_LE(error.at_grid_points[i], 1e-4) << "b_" << i + 1;
    EXPECT_LE(error.between_grid_points[i], 3e-4) << "b_" << i + 1;
  }
}

TEST_P(ShippedBasis, ShaderFormKeepsTheEndpointsThatTheCoefficientsRelyOn) {
  const auto& shader_basis = runtime::shipped_shader_basis(GetParam());
  const auto grazing = runtime::evaluate_shader_basis(shader_basis, 0.0);
  const auto normal = runtime::evaluate_shader_basis(shader_basis, 1.0);
  EXPECT_EQ(grazing[0], 1.0);
  EXPECT_NEAR(grazing[1], 1.0, 1e-4);
  EXPECT_NEAR(normal[1], 0.0, 1e-4);
  for (std::size_t i = 2; i < 4; ++i) {
    EXPECT_NEAR(grazing[i], 0.0, 1e-4);
    EXPECT_NEAR(normal[i], 0.0, 1e-4);
  }
}

TEST(BasisPolynomial, SegmentsSplitTheSquareRootOfTheCosineEvenly) {
  EXPECT_EQ(runtime::polynomial_position(0.0).segment, 0u);
  EXPECT_EQ(runtime::polynomial_position(0.0).t, -1.0);
  EXPECT_EQ(runtime::polynomial_position(1.0 / 16.0).segment, 1u);
  EXPECT_EQ(runtime::polynomial_position(1.0 / 16.0).t, -1.0);
  EXPECT_EQ(runtime::polynomial_position(1.0).segment, 3u);
  EXPECT_EQ(runtime::polynomial_position(1.0).t, 1.0);
  EXPECT_EQ(runtime::polynomial_position(-0.5).segment, 0u);
  EXPECT_EQ(runtime::polynomial_position(2.0).t, 1.0);
}

TEST(PaperBasis, GeneratedSourceRoundTripsEveryDigit) {
  FittedBasis tiny;
  tiny.tables = {{{1.0, 0.1 + 0.2, 0.0}, {0.0, -1e-300, 0.0}, {0.0, 1.0 / 3.0, 0.0}}};
  tiny.probe_indices = {1, 1};
  const std::string source = basis_table_source(tiny);
  EXPECT_NE(source.find("0.30000000000000004"), std::string::npos);
  EXPECT_NE(source.find("-1e-300"), std::string::npos);
  EXPECT_NE(source.find("0.3333333333333333"), std::string::npos);
  EXPECT_NE(source.find("Generated by `matc basis fit --basis paper`"), std::string::npos);
}

TEST(ShippedBases, NamesRoundTripAndTheDefaultIsTheClosedForm) {
  EXPECT_EQ(runtime::kDefaultBasis, runtime::BasisKind::powers);
  EXPECT_EQ(runtime::shipped_basis().kind, runtime::BasisKind::powers);
  EXPECT_EQ(runtime::shipped_shader_basis().form, runtime::ShaderBasisForm::powers);
  for (const auto kind : runtime::kShippedBases)
    EXPECT_EQ(runtime::basis_from_name(runtime::basis_name(kind)), kind);
  EXPECT_EQ(runtime::basis_from_name("f82"), runtime::BasisKind::f82);
  EXPECT_FALSE(runtime::basis_from_name("schlick"));
}

// Each closed form is what its table samples, and what the shaders compute from their literals:
// b_1 = m^a, b_2 = mu m^b, b_3 = mu m^(a+b), the exponents written out here.
TEST(ClosedFormBases, TablesSampleTheClosedForms) {
  struct Expected {
    runtime::BasisKind kind;
    int edge, lobe, product;
  };
  for (const Expected& expected : {Expected{runtime::BasisKind::powers, 6, 3, 9},
                                   Expected{runtime::BasisKind::f82, 5, 6, 11}}) {
    const BasisView basis = runtime::shipped_basis(expected.kind);
    EXPECT_EQ(basis.kind, expected.kind);
    for (std::size_t j = 0; j < basis.samples(); j += 37) {
      const double mu = basis.mu_at(j);
      const double m = 1.0 - mu;
      EXPECT_NEAR(basis.tables[0][j], std::pow(m, expected.edge), 1e-15);
      EXPECT_NEAR(basis.tables[1][j], mu * std::pow(m, expected.lobe), 1e-15);
      EXPECT_NEAR(basis.tables[2][j], mu * std::pow(m, expected.product), 1e-15);
      EXPECT_EQ(runtime::evaluate_shader_basis(runtime::shipped_shader_basis(expected.kind), mu),
                basis.at_index(j));
    }
  }
}

// F82-tint's curve, F0 + (1 - F0) m^5 - a mu m^6, is c = (F0, 1 - F0, -a, 0) in the f82 basis
// at every cosine: the span holds it exactly, not to a fit.
TEST(F82Basis, SpansEveryF82TintCurve) {
  const runtime::ShaderBasis& basis = runtime::shipped_shader_basis(runtime::BasisKind::f82);
  for (const double f0 : {0.02, 0.5, 0.97}) {
    for (const double a : {-0.3, 0.0, 0.8}) {
      for (int k = 0; k <= 100; ++k) {
        const double mu = k / 100.0;
        const auto b = runtime::evaluate_shader_basis(basis, mu);
        const double curve =
            f0 + (1.0 - f0) * std::pow(1.0 - mu, 5) - a * mu * std::pow(1.0 - mu, 6);
        EXPECT_NEAR(f0 * b[0] + (1.0 - f0) * b[1] - a * b[2], curve, 1e-15) << f0 << " " << mu;
      }
    }
  }
}

TEST(ClosedFormBases, HaveNoTableToFit) {
  for (const auto& [kind, form] :
       {std::pair{runtime::BasisKind::powers, runtime::ShaderBasisForm::powers},
        std::pair{runtime::BasisKind::f82, runtime::ShaderBasisForm::f82}}) {
    EXPECT_TRUE(runtime::is_closed_form(kind));
    EXPECT_EQ(std::count(runtime::kFittedBases.begin(), runtime::kFittedBases.end(), kind), 0);
    EXPECT_EQ(fit_shipped_basis(kind).shader.form, form);
    EXPECT_EQ(runtime::shipped_shader_basis(kind).form, form);
  }
  for (const auto kind : runtime::kFittedBases)
    EXPECT_FALSE(runtime::is_closed_form(kind));
}

const auto kBasisTestName = [](const auto& name) {
  return std::string(runtime::basis_name(name.param));
};
INSTANTIATE_TEST_SUITE_P(All, ShippedBasis, testing::ValuesIn(runtime::kShippedBases),
                         kBasisTestName);
INSTANTIATE_TEST_SUITE_P(All, FittedShippedBasis, testing::ValuesIn(runtime::kFittedBases),
                         kBasisTestName);

}  // namespace
}  // namespace matc
