// The shared shader library matc_fresnel.glsl / .hlsl: basis, F, LUT lookup, energy compensation.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "emit/shader_literals.h"
#include "fit/coefficient_table.h"
#include "ltc/ltc_fit.h"
#include "lut/preintegrate.h"
#include "matc/runtime/basis.h"
#include "matc/runtime/shader_basis.h"

namespace matc {

struct ShaderLibraryOptions {
  std::size_t lut_size = LutOptions{}.size;  // the table the build writes (MATC_LUT_SIZE)
  // The coefficient table's width and height (MATC_COEFFICIENT_TABLE_SIZE).
  std::size_t coefficient_table_size = kDefaultCoefficientTableSize;
  // Small tables to embed as constant arrays (--embed-lut), the first basis' then one per further
  // layer; empty for none.
  std::span<const Lut> embedded_luts;
  // The textured-metal functions (coefficient table, inverse Gulbrandsen mapping).
  bool coefficient_table_functions = true;
  // The area-light functions (LTC quad, disk and sphere lights) and the LTC table's size
  // (MATC_LTC_SIZE).
  bool area_light_functions = true;
  std::size_t ltc_size = kDefaultLtcSize;
  // The closed form of this basis' table (matc_preintegrated_basis_analytic, its checked-in
  // coefficients); none without a value.
  std::optional<runtime::BasisKind> analytic_lut = std::nullopt;
  // The table's layers after the first (--basis auto): each closed form's functions again with
  // its name appended (matc_fresnel_f82, matc_lut_texcoord_f82, ...), and matc_lut_texcoord
  // reading the first of them side by side.
  std::vector<runtime::BasisKind> further_layers;
};

std::string shader_library_source(ShaderLanguage language, const runtime::ShaderBasis& basis,
                                  const ShaderLibraryOptions& options,
                                  std::string_view inputs_hash);

}  // namespace matc
