// Everything matc ships for each basis, one record per basis: its name and description, its
// table, the form the shaders evaluate, its coefficient table (textured metals) and the closed
// form of its preintegrated table. Adding a basis is adding a record here (and its fitting recipe
// in the compiler's src/basis/basis_fit.cpp); the lookups in basis.h, shader_basis.h,
// coefficient_table.h and analytic_lut.h read these records.
#pragma once

#include <span>
#include <string_view>

#include "matc/runtime/analytic_lut.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/shader_basis.h"

namespace matc::runtime {

struct ShippedBasisRecord {
  BasisKind kind;
  std::string_view name;         // what --basis accepts and outputs record
  std::string_view description;  // one line for `matc basis`
  BasisView (*table)();          // b_1..b_3 sampled (checked in, or the closed form sampled)
  ShaderBasis (*shader_form)();  // how the shaders evaluate b_1..b_3
  CoefficientTableView (*coefficient_table)();
  const AnalyticLutCoefficients& (*analytic_lut)();
};

// The records, in kShippedBases' order.
std::span<const ShippedBasisRecord> shipped_basis_records();
const ShippedBasisRecord& shipped_basis_record(BasisKind kind);

}  // namespace matc::runtime
