// The basis b_1..b_3 as the generated shaders evaluate it: piecewise polynomials in u = sqrt(mu).
//
// A shader cannot afford the 1000-sample table, so `matc basis fit` also fits it with
// kPolynomialSegments polynomials of degree kPolynomialDegree. Segment s covers
// u in [s / S, (s + 1) / S) (the last one includes u = 1) and is a polynomial in
// t = 2 (S u - s) - 1 in [-1, 1], evaluated by Horner's rule with the highest power first.
// The coefficients are float values, so the shaders' float literals hold them exactly.
#pragma once

#include <array>
#include <cstddef>

#include "matc/runtime/basis.h"

namespace matc::runtime {

inline constexpr std::size_t kPolynomialSegments = 4;
inline constexpr std::size_t kPolynomialDegree = 6;

// Coefficients of t^degree .. t^0, each a triple (b_1, b_2, b_3).
using PolynomialSegment = std::array<std::array<double, 3>, kPolynomialDegree + 1>;
using BasisPolynomial = std::array<PolynomialSegment, kPolynomialSegments>;

// The segment a cosine falls in, and its local variable t.
struct PolynomialPosition {
  std::size_t segment = 0;
  double t = -1.0;
};
PolynomialPosition polynomial_position(double mu);

// b_0..b_3 at mu (clamped to [0, 1]), exactly the steps of the shaders' matc_basis().
std::array<double, kBasisSize> evaluate_basis_polynomial(const BasisPolynomial& polynomial,
                                                         double mu);

// The fits of the fitted bases (kFittedBases), checked in beside their tables; shader_basis.h
// has every shipped basis' shader form.
const BasisPolynomial& paper_basis_polynomial();
const BasisPolynomial& extended_basis_polynomial();

}  // namespace matc::runtime
