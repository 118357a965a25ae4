// The library's sampler runs its AVX2 clone where the CPU has AVX2; the table must not depend on
// that, so both builds must agree to the bit.
#include <gtest/gtest.h>

#include "lut/microfacet_samples.h"
#include "sampler_baseline.h"

namespace {

TEST(SamplerClones, BaselineAndDispatchedBuildsAgreeBitForBit) {
  const std::size_t count = 4099;  // not a multiple of any vector width
  const matc::HammersleySet set(count);
  std::vector<float> vdoth(count);
  std::vector<float> weight(count);
  for (const double ndotv : {0.0, 0.013, 0.5, 1.0}) {
    for (const double roughness : {0.0, 0.25, 1.0}) {
      matc::sample_microfacet_reflections(set, ndotv, roughness, vdoth.data(), weight.data());
      const std::vector<float> baseline = baseline_microfacet_samples(count, ndotv, roughness);
      for (std::size_t k = 0; k < count; ++k) {
        ASSERT_EQ(vdoth[k], baseline[k]) << "ndotv=" << ndotv << " roughness=" << roughness;
        ASSERT_EQ(weight[k], baseline[count + k])
            << "ndotv=" << ndotv << " roughness=" << roughness;
      }
    }
  }
}

}  // namespace
