#include "lut/preintegrate.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/parallel_rows.h"
#include "lut/microfacet_samples.h"

namespace matc {
namespace {

// The basis as float4 rows, so one lookup fetches all four elements at a cosine.
class InterleavedBasis {
 public:
  explicit InterleavedBasis(const runtime::BasisView& basis) : last_(basis.samples() - 1) {
    rows_.reserve(basis.samples());
    for (std::size_t j = 0; j < basis.samples(); ++j) {
      const auto b = basis.at_index(j);
      rows_.push_back({static_cast<float>(b[0]), static_cast<float>(b[1]), static_cast<float>(b[2]),
                       static_cast<float>(b[3])});
    }
  }

  // Adds weight * b_i(mu) to `sums`, with the same linear interpolation as BasisView::evaluate.
  void accumulate(float mu, float weight, std::array<float, 4>& sums) const {
    const float position = mu * static_cast<float>(last_);
    const std::size_t left = std::min(static_cast<std::size_t>(position), last_ - 1);
    const float t = position - static_cast<float>(left);
    const auto& a = rows_[left];
    const auto& b = rows_[left + 1];
    for (std::size_t i = 0; i < 4; ++i)
      sums[i] += weight * (a[i] + t * (b[i] - a[i]));
  }

 private:
  std::size_t last_;
  std::vector<std::array<float, 4>> rows_;
};

// The split-sum averages of `basis` over `count` sampled reflections (their v.h and weights).
std::array<double, 4> integrate_samples(const InterleavedBasis& basis, std::size_t count,
                                        const std::vector<float>& vdoth,
                                        const std::vector<float>& weight) {
  // Float partial sums over short blocks (fast, and their rounding stays near float epsilon),
  // carried in double across blocks.
  constexpr std::size_t kBlock = 64;
  std::array<double, 4> sums{};
  for (std::size_t start = 0; start < count; start += kBlock) {
    std::array<float, 4> partial{};
    const std::size_t end = std::min(start + kBlock, count);
    for (std::size_t k = start; k < end; ++k)
      basis.accumulate(vdoth[k], weight[k], partial);
    for (std::size_t i = 0; i < 4; ++i)
      sums[i] += partial[i];
  }
  for (double& sum : sums)
    sum /= static_cast<double>(count);
  return sums;
}

std::array<double, 4> integrate_texel(const InterleavedBasis& basis, const HammersleySet& set,
                                      double ndotv, double roughness, std::vector<float>& vdoth,
                                      std::vector<float>& weight) {
  sample_microfacet_reflections(set, ndotv, roughness, vdoth.data(), weight.data());
  return integrate_samples(basis, set.size(), vdoth, weight);
}

}  // namespace

std::array<double, runtime::kBasisSize> preintegrate_basis(const runtime::BasisView& basis,
                                                           double ndotv, double roughness,
                                                           std::size_t samples) {
  const HammersleySet set(samples);
  std::vector<float> vdoth(samples);
  std::vector<float> weight(samples);
  return integrate_texel(InterleavedBasis(basis), set, ndotv, roughness, vdoth, weight);
}

Lut preintegrate_lut(const runtime::BasisView& basis, const LutOptions& options) {
  return std::move(preintegrate_luts({&basis, 1}, options).front());
}

std::vector<Lut> preintegrate_luts(std::span<const runtime::BasisView> bases,
                                   const LutOptions& options) {
  if (options.size < kMinLutSize || options.size > kMaxLutSize) {
    throw std::invalid_argument("LUT size must be within [2, 4096]");
  }
  if (options.samples < 1 || options.samples > kMaxLutSamples) {
    throw std::invalid_argument("LUT samples per texel must be within [1, 1048576]");
  }
  std::vector<Lut> luts(bases.size());
  std::vector<InterleavedBasis> interleaved;
  for (std::size_t b = 0; b < bases.size(); ++b) {
    luts[b].size = options.size;
    luts[b].samples = options.samples;
    luts[b].texels.resize(options.size * options.size * runtime::kBasisSize);
    interleaved.emplace_back(bases[b]);
  }
  const std::size_t size = options.size;
  const HammersleySet set(options.samples);
  const double last = static_cast<double>(size - 1);
  fill_rows_in_parallel(size, options.threads, [&] {
    return [&, vdoth = std::vector<float>(options.samples),
            weight = std::vector<float>(options.samples)](std::size_t y) mutable {
      const double roughness = static_cast<double>(y) / last;
      for (std::size_t x = 0; x < size; ++x) {
        const double ndotv = runtime::lut_ndotv_from_u(static_cast<double>(x) / last);
        // The GGX samples of this texel once, every basis integrated over them.
        sample_microfacet_reflections(set, ndotv, roughness, vdoth.data(), weight.data());
        for (std::size_t b = 0; b < bases.size(); ++b) {
          const auto bbar = integrate_samples(interleaved[b], set.size(), vdoth, weight);
          float* texel = &luts[b].texels[(y * size + x) * runtime::kBasisSize];
          for (std::size_t i = 0; i < runtime::kBasisSize; ++i)
            texel[i] = static_cast<float>(bbar[i]);
        }
      }
    };
  });
  return luts;
}

}  // namespace matc
