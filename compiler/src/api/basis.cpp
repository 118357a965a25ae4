#include "matc/api/basis.h"

#include "basis/basis_polynomial_fit.h"
#include "checked_options.h"
#include "matc/runtime/powers_basis.h"
#include "matc/runtime/shader_basis.h"
#include "matc/runtime/shipped_bases.h"

namespace matc::api {

BasisDescription describe_basis(std::string_view name) {
  const runtime::BasisKind kind = basis_of({std::string(name), {}, {}});
  const runtime::BasisView basis = runtime::shipped_basis(kind);
  BasisDescription out;
  out.name = runtime::basis_name(kind);
  out.description = runtime::shipped_basis_record(kind).description;
  out.closed_form = runtime::is_closed_form(kind);
  if (out.closed_form) {
    const runtime::ClosedFormExponents exponents = runtime::closed_form_exponents(kind);
    out.closed_form_exponents = {exponents.edge, exponents.lobe};
  }
  for (std::size_t j = 0; j < basis.samples(); ++j) {
    out.mu.push_back(basis.mu_at(j));
    const auto values = basis.at_index(j);
    out.b.push_back({values[0], values[1], values[2], values[3]});
  }
  out.probes = {basis.probe_mu(0), basis.probe_mu(1)};
  if (!out.closed_form) {
    const PolynomialFitError error =
        polynomial_fit_error(runtime::shipped_shader_basis(kind).polynomial, basis);
    out.polynomial_error_at_samples = error.at_grid_points;
    out.polynomial_error_between_samples = error.between_grid_points;
  }
  return out;
}

}  // namespace matc::api
