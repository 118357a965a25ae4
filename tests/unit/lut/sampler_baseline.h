#pragma once

#include <cstddef>
#include <vector>

// V.H for every sample, then the weights: computed by the baseline (no AVX2 clone) build.
std::vector<float> baseline_microfacet_samples(std::size_t count, double ndotv, double roughness);
