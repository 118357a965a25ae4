// The basis' own coefficient solve for one colour channel of a Gulbrandsen conductor (r, g), fast
// enough to run once per distinct (r, g) of an 8-bit texture pair (`matc bake`): the same cosines
// and the same Lawson iterations as solve_coefficients, specialised to its two unknowns.
#pragma once

#include <cstddef>
#include <vector>

#include "matc/runtime/basis.h"
#include "matc/runtime/fresnel.h"

namespace matc {

struct ChannelSolution {
  runtime::ChannelCoefficients coefficients{};  // c_0 = r, c_1 = 1 - r, c_2, c_3
  double max_error = 0.0;  // max |sum c_i b_i - exact| over the solve's cosines
};

class ConductorSolver {
 public:
  explicit ConductorSolver(runtime::BasisKind basis);

  // Agrees with solve_coefficients on the same conductor to rounding
  // (tests/unit/bake/bake_test.cpp); reflectivity and edge tint are clamped to [0, 1], r = 1 gives
  // F = 1 (c = 1, 0, 0, 0).
  ChannelSolution solve(double reflectivity, double edge_tint) const;

  runtime::BasisKind basis() const { return basis_; }

 private:
  runtime::BasisKind basis_;
  std::vector<double> mu_;            // the solve's cosines
  std::vector<double> b1_, b2_, b3_;  // the shader basis there
  std::vector<float> b2_float_, b3_float_;
};

}  // namespace matc
