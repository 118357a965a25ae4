// The preintegrated table bbar_i(NdotV, roughness) and the coefficient table c_2, c_3 (r, g) as
// Python objects: their texels as read-only numpy arrays, their layouts, and sampling exactly as
// the CPU runtime (and a GPU sampler) reads them.
#pragma once

#include <memory>

#include "matc/fit/coefficient_table.h"
#include "matc/formats/table_format.h"
#include "matc/lut/preintegrate.h"
#include "matc/runtime/basis.h"

namespace matc::python {

struct PreintegratedTable {
  std::shared_ptr<const Lut> lut;  // as its file stores it (precision)
  runtime::BasisKind basis = runtime::kDefaultBasis;
  LutPrecision precision = LutPrecision::f32;
};

struct CoefficientTableObject {
  std::shared_ptr<const CoefficientTable> table;  // as its file stores it (precision)
  LutPrecision precision = LutPrecision::f16;
};

// The table `matc` writes by default for `basis` (and `matc eval` samples): baked on first use,
// once per process, with the GIL released.
const PreintegratedTable& default_preintegrated_table(runtime::BasisKind basis);

}  // namespace matc::python
