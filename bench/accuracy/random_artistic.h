// The random artistic (r, g) inputs the accuracy study and tables share: fixed-seed mt19937_64
// draws (its output is specified by the standard; the library's distributions are not, so the
// mapping to [0, 1) is done here).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace matc::bench {

// Fixed-seed draws in [0, 1): the top 53 bits of mt19937_64's output.
class UnitDraws {
 public:
  explicit UnitDraws(std::uint64_t seed) : generator_(seed) {}
  double operator()() { return static_cast<double>(generator_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 generator_;
};

inline std::vector<std::array<double, 2>> random_artistic_inputs(std::size_t count, double r_max) {
  UnitDraws unit(20201);
  std::vector<std::array<double, 2>> inputs;
  for (std::size_t i = 0; i < count; ++i) {
    const double r = unit() * r_max;
    inputs.push_back({r, unit()});
  }
  return inputs;
}

}  // namespace matc::bench
