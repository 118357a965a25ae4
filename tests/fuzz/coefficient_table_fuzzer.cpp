// libFuzzer target for the textured-metal inputs: the per-channel values parser of `matc eval`'s
// `--reflectivity` / `--edge-tint` (the public api::parse_channel_values) on arbitrary text, and
// the runtime's coefficient-table path (artistic_from_ior, coefficients_from_table, F) on arbitrary
// doubles, NaN and infinities included. Whatever comes in, coefficients and F stay finite, c_0 = r
// stays in [0, 1], and nothing reads outside the table. Built with -DMATC_BUILD_FUZZERS=ON (clang).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

#include "matc/api/options.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/shader_basis.h"

namespace {

void check_finite(const matc::runtime::Coefficients& coefficients) {
  for (const auto& channel : coefficients) {
    if (!(channel[0] >= 0.0 && channel[0] <= 1.0)) __builtin_trap();
    for (const double c : channel)
      if (!std::isfinite(c)) __builtin_trap();
  }
  const auto f =
      matc::runtime::evaluate_fresnel(coefficients, matc::runtime::shipped_shader_basis(), 0.5);
  for (const double value : f)
    if (!std::isfinite(value)) __builtin_trap();
}

// The values, or nothing when the parser refused them with a message (any other outcome is a
// finding).
std::optional<matc::runtime::Rgb> channel_values(const char* label, const std::string& text) {
  try {
    return matc::api::parse_channel_values(label, text);
  } catch (const std::invalid_argument& error) {
    if (std::string(error.what()).empty()) __builtin_trap();
    return std::nullopt;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The option parser: the text before the first newline is --reflectivity, the rest --edge-tint.
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t newline = text.find('\n');
  const auto r = channel_values("--reflectivity", text.substr(0, newline));
  const auto g = channel_values(
      "--edge-tint", newline == std::string::npos ? std::string() : text.substr(newline + 1));
  const auto table = matc::runtime::shipped_coefficient_table();
  if (r && g) check_finite(matc::runtime::coefficients_from_table(table, *r, *g));

  // The runtime path on raw doubles: the first 48 bytes as n and k per channel.
  if (size >= 6 * sizeof(double)) {
    double values[6];
    std::memcpy(values, data, sizeof values);
    const auto artistic = matc::runtime::artistic_from_ior({values[0], values[1], values[2]},
                                                           {values[3], values[4], values[5]});
    check_finite(
        matc::runtime::coefficients_from_table(table, artistic.reflectivity, artistic.edge_tint));
    check_finite(matc::runtime::coefficients_from_table(table, {values[0], values[1], values[2]},
                                                        {values[3], values[4], values[5]}));
  }
  return 0;
}
