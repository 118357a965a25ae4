#include "matc/runtime/f0_table.h"

#include <cmath>
#include <stdexcept>

#include "texel_axis.h"

namespace matc::runtime {
namespace {

// Channel c's entries interpolated at f0: c_0..c_3 as stored.
ChannelCoefficients interpolated(const std::array<Coefficients, kF0TableEntries>& entries,
                                 std::size_t channel, double f0) {
  const auto [left, weight] =
      texel_axis_position(std::sqrt(std::sqrt(unit_clamp(f0))), kF0TableEntries);
  const ChannelCoefficients& a = entries[left][channel];
  const ChannelCoefficients& b = entries[left + 1][channel];
  ChannelCoefficients out{};
  for (std::size_t i = 0; i < kBasisSize; ++i)
    out[i] = a[i] + weight * (b[i] - a[i]);
  return out;
}

}  // namespace

double f0_table_entry_f0(std::size_t entry) {
  const double x = static_cast<double>(entry) / static_cast<double>(kF0TableEntries - 1);
  return (x * x) * (x * x);
}

Coefficients coefficients_from_f0_table(const F0Table& table, const Rgb& f0) {
  Coefficients out{};
  for (std::size_t c = 0; c < 3; ++c) {
    out[c] = interpolated(table.in_air, c, f0[c]);
    out[c][0] = unit_clamp(f0[c]);
    out[c][1] = 1.0 - out[c][0];
  }
  return out;
}

Coefficients under_coat_coefficients_from_f0_table(const F0Table& table, const Rgb& f0) {
  if (!table.under_coat) throw std::logic_error("F0 table of a bare metal: no under-coat entries");
  Coefficients out{};
  for (std::size_t c = 0; c < 3; ++c)
    out[c] = interpolated(*table.under_coat, c, f0[c]);
  return out;
}

}  // namespace matc::runtime
