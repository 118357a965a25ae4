// The public face's numeric arguments checked: std::invalid_argument naming the argument, the
// first bad element and what it takes.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace matc::api {

// Every value one `allowed` takes, else std::invalid_argument "ARGUMENT: element I is V; TAKES".
void check_each(std::string_view argument, std::span<const double> values, bool (*allowed)(double),
                std::string_view takes);
// Every value in [0, 1] (NaN refused).
void check_unit_interval(std::string_view argument, std::span<const double> values);
// NdotV and roughness as the preintegrated evaluations take them: each in [0, 1], one of each.
void check_ndotv_roughness(std::span<const double> ndotv, std::span<const double> roughness);
// A count in [low, high].
std::size_t checked_count(std::string_view argument, std::size_t value, std::size_t low,
                          std::size_t high);

}  // namespace matc::api
