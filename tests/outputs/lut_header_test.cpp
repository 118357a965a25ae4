// The C++ header `matc lut --format header` writes compiles and holds the table bit for bit.
#include <gtest/gtest.h>

#include "lut/energy.h"
#include "lut/preintegrate.h"
#include "matc_lut_generated.h"  // generated at build time by tests/CMakeLists.txt

namespace {

TEST(LutHeader, HoldsTheSameTexelsAsTheLibrary) {
  const matc::Lut lut = matc::preintegrate_lut(matc::runtime::shipped_basis(), {16, 64, 1});
  ASSERT_EQ(matc_lut::kSize, lut.size);
  ASSERT_EQ(std::size(matc_lut::kTexels), lut.texels.size());
  for (std::size_t i = 0; i < lut.texels.size(); ++i) {
    ASSERT_EQ(matc_lut::kTexels[i], lut.texels[i]) << "texel component " << i;
  }
  const auto albedo = matc::average_albedo(lut);
  ASSERT_EQ(std::size(matc_lut::kAverageAlbedo), albedo.size());
  for (std::size_t i = 0; i < albedo.size(); ++i) {
    EXPECT_EQ(matc_lut::kAverageAlbedo[i], static_cast<float>(albedo[i]));
  }
  EXPECT_EQ(matc_lut::kBasisHemisphericalAverages[0], 1.0f);
}

}  // namespace
