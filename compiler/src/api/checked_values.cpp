#include "checked_values.h"

#include <stdexcept>

#include <fmt/format.h>

namespace matc::api {

void check_each(std::string_view argument, std::span<const double> values, bool (*allowed)(double),
                std::string_view takes) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!allowed(values[i]))
      throw std::invalid_argument(
          fmt::format("{}: element {} is {}; {}", argument, i, values[i], takes));
  }
}

void check_unit_interval(std::string_view argument, std::span<const double> values) {
  check_each(
      argument, values, [](double x) { return x >= 0.0 && x <= 1.0; }, "a number in [0, 1]");
}

void check_ndotv_roughness(std::span<const double> ndotv, std::span<const double> roughness) {
  if (ndotv.size() != roughness.size()) {
    throw std::invalid_argument(
        fmt::format("ndotv and roughness: {} and {} values; one roughness per NdotV", ndotv.size(),
                    roughness.size()));
  }
  check_unit_interval("ndotv", ndotv);
  check_unit_interval("roughness", roughness);
}

std::size_t checked_count(std::string_view argument, std::size_t value, std::size_t low,
                          std::size_t high) {
  if (value < low || value > high) {
    throw std::invalid_argument(
        fmt::format("{}: {} is out of range; an integer in [{}, {}]", argument, value, low, high));
  }
  return value;
}

}  // namespace matc::api
