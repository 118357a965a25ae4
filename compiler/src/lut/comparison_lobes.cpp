#include "lut/comparison_lobes.h"

#include <cmath>

namespace matc {

ComparisonLobes::ComparisonLobes(std::size_t samples)
    : schlick_(samples), f82_(samples), zero_(samples, 0.0) {
  for (std::size_t j = 0; j < samples; ++j) {
    const double mu = static_cast<double>(j) / static_cast<double>(samples - 1);
    schlick_[j] = std::pow(1.0 - mu, 5.0);
    f82_[j] = mu * std::pow(1.0 - mu, 6.0);
  }
}

}  // namespace matc
