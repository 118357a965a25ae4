// Exact Fresnel against textbook values and an independent (real-arithmetic) formulation.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "optics/fresnel.h"
#include "optics/gulbrandsen.h"

namespace matc {
namespace {

// Conductor Fresnel in the a^2, b^2 form (Born & Wolf; Shirley, "Realistic Ray Tracing"), written
// with real numbers only, so it shares no code or branch choice with fresnel_exact.
double fresnel_conductor_reference(double mu, double n, double k) {
  const double cos_i = mu;
  const double sin2 = 1.0 - cos_i * cos_i;
  const double t = n * n - k * k - sin2;
  const double a2_plus_b2 = std::sqrt(t * t + 4.0 * n * n * k * k);
  const double a = std::sqrt(0.5 * (a2_plus_b2 + t));
  const double rs = (a2_plus_b2 - 2.0 * a * cos_i + cos_i * cos_i) /
                    (a2_plus_b2 + 2.0 * a * cos_i + cos_i * cos_i);
  const double sin_tan = sin2 / cos_i;
  const double rp = rs * (a2_plus_b2 - 2.0 * a * sin_tan + sin_tan * sin_tan) /
                    (a2_plus_b2 + 2.0 * a * sin_tan + sin_tan * sin_tan);
  return 0.5 * (rs + rp);
}

TEST(FresnelExact, NormalIncidenceOfGlassIsFourPercent) {
  EXPECT_NEAR(fresnel_exact(1.0, {1.5, 0.0}), 0.04, 1e-15);
  EXPECT_NEAR(fresnel_normal_incidence({1.5, 0.0}), 0.04, 1e-15);
}

TEST(FresnelExact, NormalIncidenceMatchesClosedFormForConductors) {
  for (const ComplexIor ior : {ComplexIor{0.2, 3.5}, ComplexIor{1.2, 7.0}, ComplexIor{2.9, 3.1}}) {
    const double expected =
        ((ior.n - 1) * (ior.n - 1) + ior.k * ior.k) / ((ior.n + 1) * (ior.n + 1) + ior.k * ior.k);
    EXPECT_NEAR(fresnel_exact(1.0, ior), expected, 1e-14);
    EXPECT_NEAR(fresnel_normal_incidence(ior), expected, 1e-15);
  }
}

TEST(FresnelExact, BrewsterAngleLeavesOnlyTheSPolarisation) {
  const double n = 1.5;
  const double theta_b = std::atan(n);
  const double theta_t = std::numbers::pi / 2 - theta_b;
  const double rs = std::pow(std::sin(theta_b - theta_t) / std::sin(theta_b + theta_t), 2);
  EXPECT_NEAR(rs, 0.1479, 1e-4);
  EXPECT_NEAR(fresnel_exact(std::cos(theta_b), {n, 0.0}), 0.5 * rs, 1e-14);
}

TEST(FresnelExact, MatchesIndependentConductorFormula) {
  for (const double n : {0.05, 0.3, 1.0, 1.7, 4.0}) {
    for (const double k : {0.01, 0.5, 2.0, 8.0}) {
      for (int j = 1; j <= 100; ++j) {
        const double mu = j / 100.0;
        EXPECT_NEAR(fresnel_exact(mu, {n, k}), fresnel_conductor_reference(mu, n, k), 1e-12)
            << "n=" << n << " k=" << k << " mu=" << mu;
      }
    }
  }
}

// IorCurve evaluates the real-arithmetic form: it must agree with the complex one for every
// index a material or a coat can make, dielectrics (k = 0) and n < 1 beyond the critical angle
// included.
TEST(FresnelConductor, ConductorFormMatchesTheComplexForm) {
  for (const double n : {0.01, 0.05, 0.3, 0.7, 1.0, 1.5, 4.0, 30.0}) {
    for (const double k : {0.0, 1e-9, 0.01, 0.5, 2.0, 8.0, 80.0}) {
      for (int j = 0; j <= 1000; ++j) {
        const double mu = j / 1000.0;
        EXPECT_NEAR(fresnel_conductor(mu, {n, k}), fresnel_exact(mu, {n, k}), 3e-12)
            << "n=" << n << " k=" << k << " mu=" << mu;
      }
    }
  }
}

TEST(FresnelExact, GrazingIncidenceReflectsEverything) {
  for (const ComplexIor ior : {ComplexIor{1.5, 0.0}, ComplexIor{0.7, 0.0}, ComplexIor{0.2, 3.0}}) {
    EXPECT_EQ(fresnel_exact(0.0, ior), 1.0);
    EXPECT_NEAR(fresnel_exact(1e-9, ior), 1.0, 1e-6);
  }
}

TEST(FresnelExact, DielectricLimitIsContinuousInK) {
  for (const double n : {1.5, 0.7}) {
    for (int j = 0; j <= 200; ++j) {
      const double mu = j / 200.0;
      EXPECT_NEAR(fresnel_exact(mu, {n, 1e-10}), fresnel_exact(mu, {n, 0.0}), 1e-8)
          << "n=" << n << " mu=" << mu;
    }
  }
}

TEST(FresnelExact, TotalInternalReflectionBeyondTheCriticalAngle) {
  const double n = 1.0 / 1.5;  // leaving glass into air
  const double cos_critical = std::sqrt(1.0 - n * n);
  for (const double mu : {0.1, 0.5, cos_critical - 1e-6}) {
    EXPECT_NEAR(fresnel_exact(mu, {n, 0.0}), 1.0, 1e-12) << mu;
  }
  EXPECT_LT(fresnel_exact(cos_critical + 0.05, {n, 0.0}), 1.0);
}

TEST(FresnelExact, StaysWithinZeroAndOne) {
  for (const double n : {0.01, 0.5, 1.0, 2.0, 10.0}) {
    for (const double k : {0.0, 0.1, 1.0, 10.0, 100.0}) {
      for (int j = 0; j <= 50; ++j) {
        const double f = fresnel_exact(j / 50.0, {n, k});
        EXPECT_GE(f, 0.0);
        EXPECT_LE(f, 1.0 + 1e-12);
      }
    }
  }
}

TEST(Schlick, EndpointsAreF0AndOne) {
  EXPECT_DOUBLE_EQ(fresnel_schlick(1.0, 0.3), 0.3);
  EXPECT_DOUBLE_EQ(fresnel_schlick(0.0, 0.3), 1.0);
  EXPECT_NEAR(fresnel_schlick(0.5, 0.0), std::pow(0.5, 5), 1e-15);
}

TEST(F82Tint, PassesThroughItsTargetAtMuBar) {
  EXPECT_NEAR(fresnel_f82_tint(kF82MuBar, 0.5, 0.42), 0.42, 1e-14);
  EXPECT_DOUBLE_EQ(fresnel_f82_tint(1.0, 0.5, 0.42), 0.5);
  EXPECT_DOUBLE_EQ(fresnel_f82_tint(0.0, 0.5, 0.42), 1.0);
  // With Schlick's own value as the target, F82-tint is Schlick.
  EXPECT_NEAR(fresnel_f82_tint(0.3, 0.5, fresnel_schlick(kF82MuBar, 0.5)),
              fresnel_schlick(0.3, 0.5), 1e-15);
}

TEST(Gulbrandsen, ReflectivityIsNormalIncidenceReflectance) {
  for (int i = 1; i < 20; ++i) {
    for (int j = 0; j <= 10; ++j) {
      const ArtisticParameters rg{i / 20.0, j / 10.0};
      EXPECT_NEAR(fresnel_exact(1.0, gulbrandsen_to_ior(rg)), rg.reflectivity, 1e-12);
    }
  }
}

TEST(Gulbrandsen, RoundTripsThroughComplexIor) {
  for (int i = 1; i < 20; ++i) {
    for (int j = 0; j <= 10; ++j) {
      const ArtisticParameters rg{i / 20.0, j / 10.0};
      const ArtisticParameters back = ior_to_gulbrandsen(gulbrandsen_to_ior(rg));
      EXPECT_NEAR(back.reflectivity, rg.reflectivity, 1e-12);
      EXPECT_NEAR(back.edge_tint, rg.edge_tint, 1e-9);
    }
  }
}

TEST(Gulbrandsen, EdgeTintExtremesMatchThePaper) {
  const double r = 0.44;
  const ComplexIor dielectric = gulbrandsen_to_ior({r, 0.0});  // g = 0: n = n_max, k = 0
  EXPECT_NEAR(dielectric.n, (1 + std::sqrt(r)) / (1 - std::sqrt(r)), 1e-12);
  EXPECT_LT(dielectric.k, 1e-6);
  const ComplexIor conductor = gulbrandsen_to_ior({r, 1.0});  // g = 1: n = n_min
  EXPECT_NEAR(conductor.n, (1 - r) / (1 + r), 1e-12);
  EXPECT_GT(conductor.k, 0.5);
}

}  // namespace
}  // namespace matc
