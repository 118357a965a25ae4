// What one `matc` run's outputs are made with (its options): which files, the tables' size,
// format and precision, the basis and the working colour space.
#pragma once

#include <cstddef>
#include <set>

#include "compile/compile.h"
#include "emit/output_layout.h"
#include "formats/table_format.h"
#include "lut/preintegrate.h"
#include "matc/runtime/basis.h"

namespace matc {

inline constexpr std::size_t kMaxEmbeddedLutSize = 64;

struct BuildOptions {
  std::set<OutputKind> emit = all_output_kinds();
  LutOptions lut;
  LutFormat lut_format = LutFormat::ktx2;
  LutPrecision lut_precision = LutPrecision::f32;
  // The coefficient table's (its format is lut_format's): f16 costs it nothing measurable.
  LutPrecision coefficient_table_precision = LutPrecision::f16;
  std::size_t embedded_lut_size = 0;  // --embed-lut: 0 for none, else 2..kMaxEmbeddedLutSize
  runtime::BasisKind basis = runtime::kDefaultBasis;  // --basis NAME: every material's
  // --basis auto: each material its own (compile/basis_choice.h), the table a layer per basis of
  // runtime::kPerMaterialBases side by side; `basis` is then the first layer's.
  bool per_material_basis = false;
  ColorOptions color;  // --color-space, --gamut-mapping
};

}  // namespace matc
