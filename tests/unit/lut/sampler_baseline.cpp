// The microfacet sampler compiled a second time, without its AVX2 clone and in its own namespace,
// so that sampler_clones_test can compare the two builds bit for bit.
#define MATC_NO_TARGET_CLONES
#define matc matc_baseline
#include "lut/microfacet_samples.cpp"  // NOLINT(bugprone-suspicious-include)
#undef matc

#include "sampler_baseline.h"

std::vector<float> baseline_microfacet_samples(std::size_t count, double ndotv, double roughness) {
  const matc_baseline::HammersleySet set(count);
  std::vector<float> out(2 * count);
  matc_baseline::sample_microfacet_reflections(set, ndotv, roughness, out.data(),
                                               out.data() + count);
  return out;
}
