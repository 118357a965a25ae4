// The closed form of the preintegrated table (issue #20): checked in current, as accurate as the
// issue asks against the texture, and well defined over the whole domain.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "lut/analytic_lut_fit.h"
#include "matc/runtime/analytic_lut.h"
#include "matc/runtime/lut.h"
#include "sanitized_build.h"

namespace {

using matc::runtime::BasisKind;

class ShippedAnalyticLut : public ::testing::TestWithParam<BasisKind> {};

TEST_P(ShippedAnalyticLut, RegenerationReproducesTheCheckedInTable) {
  // Under sanitizers the default basis' refit stands for the others: the fit's code is the same.
  if (matc::test::kSanitizedBuild && GetParam() != matc::runtime::kDefaultBasis)
    GTEST_SKIP() << "sanitized build: the default basis' regeneration only";
  const auto fitted = matc::fit_shipped_analytic_lut(GetParam());
  const auto& shipped = matc::runtime::shipped_analytic_lut(GetParam());
  // Compared as functions: monomial coefficients reach ~1e3 and cancel.
  for (std::size_t j = 0; j <= 32; ++j) {
    for (std::size_t i = 0; i <= 32; ++i) {
      const double ndotv = static_cast<double>(i) / 32.0;
      const double roughness = static_cast<double>(j) / 32.0;
      const auto a = matc::runtime::preintegrated_basis_analytic(fitted, ndotv, roughness);
      const auto b = matc::runtime::preintegrated_basis_analytic(shipped, ndotv, roughness);
      for (std::size_t c = 0; c < 4; ++c) {
        ASSERT_NEAR(a[c], b[c], 1e-9)
            << "bbar_" << c << " at NdotV " << ndotv << ", roughness " << roughness
            << ": rerun `matc basis analytic-lut --basis " << matc::runtime::basis_name(GetParam())
            << " -o runtime/src/generated/" << matc::runtime::basis_name(GetParam())
            << "_analytic_lut_table.cpp`";
      }
    }
  }
}

TEST_P(ShippedAnalyticLut, MeetsTheTargetsAgainstTheTexture) {
  const auto basis = matc::runtime::shipped_basis(GetParam());
  const matc::Lut texture = matc::preintegrate_lut(basis, matc::LutOptions{});
  const auto error =
      matc::analytic_lut_error(matc::runtime::shipped_analytic_lut(GetParam()), texture, basis);
  EXPECT_LE(error.max, 0.005);
  EXPECT_LE(error.mean, 5e-4);
  EXPECT_GT(error.max, 0.0);  // the measure sees a difference at all
}

INSTANTIATE_TEST_SUITE_P(All, ShippedAnalyticLut, ::testing::ValuesIn(matc::runtime::kShippedBases),
                         [](const auto& name) {
                           return std::string(matc::runtime::basis_name(name.param));
                         });

TEST(AnalyticLut, CoordinatesCoverTheSquareWithoutASingularity) {
  using matc::runtime::analytic_lut_coordinates;
  // Mirror-like rows are the y = 1 edge, the grazing column the y ~ -1 edge, and the corner
  // NdotV = roughness = 0 (where the table is discontinuous) is taken as a mirror.
  EXPECT_DOUBLE_EQ(analytic_lut_coordinates(0.5, 0.0)[1], 1.0);
  EXPECT_DOUBLE_EQ(analytic_lut_coordinates(0.0, 0.0)[1], 1.0);
  EXPECT_LT(analytic_lut_coordinates(0.0, 1.0)[1], -0.99);
  EXPECT_NEAR(analytic_lut_coordinates(1.0, 1.0)[0], 1.0, 1e-15);
  EXPECT_NEAR(analytic_lut_coordinates(0.0, 0.0)[0], std::sqrt(2.0) * 0.01 - 1.0, 1e-15);
  for (double ndotv : {-1.0, 0.0, 0.3, 1.0, 2.0}) {
    for (double roughness : {-1.0, 0.0, 0.4, 1.0, 2.0}) {
      const auto [x, y] = analytic_lut_coordinates(ndotv, roughness);
      EXPECT_TRUE(std::isfinite(x) && std::isfinite(y));
      EXPECT_GE(x, -1.0);
      EXPECT_LE(x, 1.0 + 1e-15);
      EXPECT_GE(y, -1.0);
      EXPECT_LE(y, 1.0);
    }
  }
}

TEST(AnalyticLut, FollowsTheMirrorAndTheFurnace) {
  // At roughness 0 the table is the basis itself; bbar_0 (b_0 = 1) is the table's albedo.
  const auto basis = matc::runtime::shipped_basis();
  const auto& analytic = matc::runtime::shipped_analytic_lut(matc::runtime::kDefaultBasis);
  for (double mu : {0.2, 0.5, 0.9}) {
    const auto bbar = matc::runtime::preintegrated_basis_analytic(analytic, mu, 0.0);
    const auto b = basis.evaluate(mu);
    for (std::size_t c = 0; c < 4; ++c)
      EXPECT_NEAR(bbar[c], b[c], 0.01) << "b_" << c << " at mu " << mu;
  }
  EXPECT_NEAR(matc::runtime::preintegrated_basis_analytic(analytic, 1.0, 0.0)[0], 1.0, 0.005);
}

// matc_energy_compensation reads the albedo bbar_0: 1 + F0 (1 - E) / E from the closed form must
// stay near the texture's for the brightest F0 (1), where the difference is largest.
TEST(AnalyticLut, EnergyCompensationFollowsTheTexture) {
  const auto basis = matc::runtime::shipped_basis();
  const matc::Lut texture = matc::preintegrate_lut(basis, matc::LutOptions{});
  const auto& analytic = matc::runtime::shipped_analytic_lut(matc::runtime::kDefaultBasis);
  const auto compensation = [](double albedo) {
    albedo = std::max(albedo, 1e-4);
    return 1.0 + (1.0 - albedo) / albedo;
  };
  double worst = 0.0;
  for (std::size_t j = 0; j <= 64; ++j) {
    for (std::size_t i = 0; i <= 64; ++i) {
      const double ndotv = static_cast<double>(i) / 64.0;
      const double roughness = static_cast<double>(j) / 64.0;
      const double closed_form =
          matc::runtime::preintegrated_basis_analytic(analytic, ndotv, roughness)[0];
      const double fetched = matc::runtime::sample_lut(texture.view(), ndotv, roughness)[0];
      worst = std::max(worst, std::abs(compensation(closed_form) - compensation(fetched)));
    }
  }
  EXPECT_LE(worst, 0.01);
  EXPECT_GT(worst, 0.0);
}

}  // namespace
