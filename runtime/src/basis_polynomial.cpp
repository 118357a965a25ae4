#include "matc/runtime/basis_polynomial.h"

#include <algorithm>
#include <cmath>

namespace matc::runtime {

PolynomialPosition polynomial_position(double mu) {
  const double scaled = std::sqrt(std::clamp(mu, 0.0, 1.0)) * double{kPolynomialSegments};
  // u = 1 belongs to the last segment (t = 1) rather than to a segment past the end.
  const std::size_t segment = std::min(static_cast<std::size_t>(scaled), kPolynomialSegments - 1);
  return {segment, 2.0 * (scaled - static_cast<double>(segment)) - 1.0};
}

std::array<double, kBasisSize> evaluate_basis_polynomial(const BasisPolynomial& polynomial,
                                                         double mu) {
  const PolynomialPosition position = polynomial_position(mu);
  const PolynomialSegment& segment = polynomial[position.segment];
  std::array<double, kBasisSize> values{1.0, 0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < 3; ++i) {
    double value = segment[0][i];
    for (std::size_t power = 1; power <= kPolynomialDegree; ++power)
      value = value * position.t + segment[power][i];
    values[i + 1] = value;
  }
  return values;
}

}  // namespace matc::runtime
