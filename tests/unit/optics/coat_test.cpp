// The coat's optics (optics/coat.h) and the Monte-Carlo layered reference
// (lut/layered_reference.h).
#include <gtest/gtest.h>

#include <cmath>

#include "lut/layered_reference.h"
#include "optics/coat.h"

namespace matc {
namespace {

TEST(Coat, RefractedCosineRunsFromTheCriticalCosineToOne) {
  EXPECT_DOUBLE_EQ(refracted_cosine(1.0, 1.5), 1.0);
  EXPECT_NEAR(refracted_cosine(0.0, 1.5), std::sqrt(1.0 - 1.0 / 2.25), 1e-15);
  EXPECT_NEAR(refracted_cosine(0.3, 1.6), std::sqrt(1.0 - (1.0 - 0.09) / 2.56), 1e-15);
}

TEST(Coat, TintIsTheColourHeadOnAndDeeperAtAngles) {
  EXPECT_DOUBLE_EQ(coat_round_trip_transmittance(0.6, 1.0), 0.6);
  EXPECT_NEAR(coat_round_trip_transmittance(0.6, 0.5), 0.36, 1e-15);
  EXPECT_EQ(coat_round_trip_transmittance(1.0, 0.2), 1.0);
  EXPECT_EQ(coat_round_trip_transmittance(0.0, 0.2), 0.0);
}

TEST(Coat, BaseThroughTheCoatSumsItsBounces) {
  // No coat reflection: the base as it is.
  EXPECT_DOUBLE_EQ(coated_base_reflectance(0.0, 0.7), 0.7);
  // (1 - f)^2 v / (1 - f v), written out.
  EXPECT_NEAR(coated_base_reflectance(0.04, 0.9), 0.96 * 0.96 * 0.9 / (1.0 - 0.036), 1e-15);
  // A perfect mirror under any coat reflects what enters: (1 - f).
  EXPECT_NEAR(coated_base_reflectance(0.3, 1.0), 0.7, 1e-15);
  // Grazing: the coat reflects everything, nothing reaches the base.
  EXPECT_EQ(coated_base_reflectance(1.0, 1.0), 0.0);
}

TEST(Coat, UnderCoatCurveIsTheMetalAtTheCosinesInsideTheCoat) {
  const ComplexIor metal{0.2, 3.5};
  const double coat_ior = 1.5;
  const UnderCoatCurve curve(
      std::make_unique<IorCurve>(std::array<ComplexIor, 3>{
          under_coat(metal, coat_ior), under_coat(metal, coat_ior), under_coat(metal, coat_ior)}),
      coat_ior);
  for (const double mu : {0.0, 0.3, 0.8, 1.0}) {
    const double expected =
        fresnel_exact(refracted_cosine(mu, coat_ior), {metal.n / coat_ior, metal.k / coat_ior});
    EXPECT_DOUBLE_EQ(curve.at(mu)[1], expected) << mu;
  }
  ASSERT_TRUE(curve.grazing_value());
  EXPECT_LT((*curve.grazing_value())[0], 1.0);
}

// Smooth coat over a smooth metal: every path is specular, so the random walk must find the
// closed-form layered reflectance (the bounce series) at every angle.
TEST(LayeredReference, SmoothLayersMatchTheClosedForm) {
  const std::array<ComplexIor, 3> metal = {ComplexIor{0.27, 3.6}, ComplexIor{0.6, 2.6},
                                           ComplexIor{1.2, 2.3}};
  const double coat_ior = 1.5;
  const Rgb color = {0.9, 0.7, 0.5};
  std::array<ComplexIor, 3> in_coat{};
  for (std::size_t c = 0; c < 3; ++c)
    in_coat[c] = under_coat(metal[c], coat_ior);
  const IorCurve in_air(metal);
  const IorCurve metal_in_coat(in_coat);
  const UnderCoatCurve under(std::make_unique<IorCurve>(in_coat), coat_ior);
  const LayeredCurve exact(in_air, under, 1.0, coat_ior, color);
  const LayeredSurface surface{in_air, metal_in_coat, CoatInput{1.0, coat_ior, 0.0, color}, 0.0};
  for (const double ndotv : {0.15, 0.5, 1.0}) {
    const LayeredEstimate estimate = layered_albedo(surface, ndotv, 1u << 14);
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_NEAR(estimate.mean[c], exact.at(ndotv)[c], 4.0 * estimate.standard_error[c] + 1e-3)
          << "ndotv " << ndotv << " channel " << c;
    }
  }
}

// A weight of 0 leaves the bare metal: the random walk's mix gives its single-scattering GGX
// albedo, which never exceeds the smooth curve's value.
TEST(LayeredReference, ZeroWeightIsTheBareMetal) {
  const std::array<ComplexIor, 3> metal = {ComplexIor{0.27, 3.6}, ComplexIor{0.27, 3.6},
                                           ComplexIor{0.27, 3.6}};
  const IorCurve in_air(metal);
  const LayeredSurface surface{in_air, in_air, CoatInput{0.0, 1.5, 0.2, {1.0, 1.0, 1.0}}, 0.0};
  const LayeredEstimate estimate = layered_albedo(surface, 0.7, 1u << 12);
  EXPECT_NEAR(estimate.mean[0], in_air.at(0.7)[0], 1e-3);
}

}  // namespace
}  // namespace matc
