// A shipped Fresnel basis b_0..b_3 (docs/accuracy.md): what `matc basis` shows. Native builds.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace matc::api {

struct BasisDescription {
  std::string name;          // e.g. "powers"
  std::string description;   // one line
  bool closed_form = false;  // the shaders evaluate a closed form (else polynomials of a table)
  // A closed form's exponents: b_1 = m^a, b_2 = mu m^b, b_3 = b_1 b_2 with m = 1 - mu ({a, b}).
  std::array<int, 2> closed_form_exponents{};
  std::vector<double> mu;                // the table's cosines, 0 to 1
  std::vector<std::array<double, 4>> b;  // b_0..b_3 at each cosine
  std::array<double, 2> probes{};        // the paper's two probe cosines
  // For a tabulated basis, the shaders' polynomials against the table: max |polynomial - table|
  // for b_1, b_2, b_3 at the table's cosines and on a 16x finer grid between them.
  std::array<double, 3> polynomial_error_at_samples{};
  std::array<double, 3> polynomial_error_between_samples{};
};

// The basis by --basis's names (empty: the default); another name throws std::invalid_argument.
BasisDescription describe_basis(std::string_view name = {});

}  // namespace matc::api
