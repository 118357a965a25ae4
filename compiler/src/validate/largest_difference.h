// How the checks compare a device result with the CPU runtime's (internal to src/validate/).
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include "matc/runtime/fresnel.h"
#include "validate/device_check.h"

namespace matc {

// Keeps the largest |actual - expected| over the three channels in `quantity`, with the query.
inline void record_largest(CheckedQuantity& quantity, const runtime::Rgb& expected,
                           const float* actual, std::size_t query) {
  for (std::size_t channel = 0; channel < 3; ++channel) {
    const double difference = std::abs(static_cast<double>(actual[channel]) - expected[channel]);
    // A NaN from the device must fail, not compare false and pass.
    if (std::isnan(difference) || difference > quantity.max_abs) {
      quantity.max_abs =
          std::isnan(difference) ? std::numeric_limits<double>::infinity() : difference;
      quantity.worst_query = query;
    }
  }
}

}  // namespace matc
