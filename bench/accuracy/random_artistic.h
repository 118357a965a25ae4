// The random artistic (r, g) inputs the accuracy study and tables share: fixed-seed mt19937_64
// draws (its output is specified by the standard; the library's distributions are not, so the
// mapping to [0, 1) is done here).
#pragma once

#include <array>
#include <cstddef>
#include <random>
#include <vector>

namespace matc::bench {

inline std::vector<std::array<double, 2>> random_artistic_inputs(std::size_t count, double r_max) {
  std::mt19937_64 generator(20201);
  const auto unit = [&] { return static_cast<double>(generator() >> 11) * 0x1.0p-53; };
  std::vector<std::array<double, 2>> inputs;
  for (std::size_t i = 0; i < count; ++i) {
    const double r = unit() * r_max;
    inputs.push_back({r, unit()});
  }
  return inputs;
}

}  // namespace matc::bench
