#include "matc/runtime/shipped_bases.h"

#include <algorithm>
#include <array>

#include "matc/runtime/powers_basis.h"

namespace matc::runtime {

// Defined by the generated closed-form tables (src/generated/<basis>_analytic_lut_table.cpp).
const AnalyticLutCoefficients& powers_analytic_lut();
const AnalyticLutCoefficients& extended_analytic_lut();
const AnalyticLutCoefficients& paper_analytic_lut();
const AnalyticLutCoefficients& f82_analytic_lut();

namespace {

constexpr std::array<ShippedBasisRecord, 4> kRecords = {{
    {BasisKind::powers, "powers",
     "b_1 = (1 - mu)^6, b_2 = mu (1 - mu)^3, b_3 = mu (1 - mu)^9 in closed form; near-minimax "
     "coefficients",
     powers_basis, ShaderBasis::powers, powers_coefficient_table, powers_analytic_lut},
    {BasisKind::extended, "extended",
     "the authors' dielectrics extended with conductors, curves weighted by 1 - F0; "
     "near-minimax coefficients",
     extended_basis, [] { return ShaderBasis(extended_basis_polynomial()); },
     extended_coefficient_table, extended_analytic_lut},
    {BasisKind::paper, "paper", "Belcour, Bati, Barla 2020; coefficients matched at the probes",
     paper_basis, [] { return ShaderBasis(paper_basis_polynomial()); }, paper_coefficient_table,
     paper_analytic_lut},
    {BasisKind::f82, "f82",
     "b_1 = (1 - mu)^5, b_2 = mu (1 - mu)^6 (F82-tint's span), b_3 = mu (1 - mu)^11 in closed "
     "form; near-minimax coefficients",
     f82_basis, ShaderBasis::f82, f82_coefficient_table, f82_analytic_lut},
}};

static_assert(kRecords.size() == kShippedBases.size());
static_assert([] {
  for (std::size_t i = 0; i < kRecords.size(); ++i)
    if (kRecords[i].kind != kShippedBases[i]) return false;
  return true;
}());

}  // namespace

std::span<const ShippedBasisRecord> shipped_basis_records() {
  return kRecords;
}

const ShippedBasisRecord& shipped_basis_record(BasisKind kind) {
  return *std::find_if(kRecords.begin(), kRecords.end(),
                       [kind](const ShippedBasisRecord& record) { return record.kind == kind; });
}

}  // namespace matc::runtime
