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
  // --basis auto, the default: each material its own (compile/basis_choice.h), the table a layer
  // per basis of runtime::kPerMaterialBases side by side; `basis` is then the first layer's.
  // false: --basis NAME, `basis` every material's.
  bool per_material_basis = true;
  runtime::BasisKind basis = runtime::kDefaultBasis;
  ColorOptions color;  // --color-space, --gamut-mapping
};

// A one-basis build (--basis NAME): one layer, every material on `basis`. What renders and
// studies that bind the table beside another of one layer (Schlick's lobe) build.
inline BuildOptions one_basis_build(runtime::BasisKind basis = runtime::kDefaultBasis) {
  BuildOptions options;
  options.per_material_basis = false;
  options.basis = basis;
  return options;
}

}  // namespace matc
