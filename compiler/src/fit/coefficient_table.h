// Fitting the coefficient table (layout: matc/runtime/coefficient_table.h): every texel is the
// per-material coefficient solve of one Gulbrandsen conductor (r, g), so a shader that samples
// the table gets what compiling that material would give, up to filtering.
//
// The shipped layout is one point of a small design space that bench/accuracy/table_study.cpp
// explores (docs/accuracy.md, "The coefficient table"); the variants exist for that study.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "matc/runtime/basis.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/fresnel.h"

namespace matc {

// Where the texel columns sit along the reflectivity axis.
enum class ReflectivityAxis {
  // u = (r^(1/4) + r^2) / 2: texels crowd at low r, where the curves change fastest, and near
  // r = 1, where the coefficients do; square roots and multiply-adds in a shader (shipped)
  fourth_root_plus_square,
  cube_root,  // u = r^(1/3): texels follow curves that change fastest at low r (shipped until issue
              // #28)
  square_root,  // u = sqrt(r): fewer texels near r = 0
  fourth_root,  // u = r^(1/4) = sqrt(sqrt(r)): more texels near r = 0, one square root more
  linear,       // u = r
  stretched_square_root,  // u = 2 s / (1 + s), s = sqrt(r): twice the texels at low r, half at 1
};

// Where the texel rows sit along the edge-tint axis.
enum class EdgeTintAxis {
  // v = log(n_max / n) / log(n_max / n_min): even in the curves' change (shipped until #28; two
  // log2 and three divisions a channel in a shader)
  log_ior,
  linear,       // v = g
  inverse_ior,  // v = (1/n - 1/n_max) / (1/n_min - 1/n_max) = g (1 - delta) / (1 - g delta)
  // v = 1 - (1 - g)^(1/k): rows crowd towards g = 1 like log n's, from square roots alone.
  complement_square_root,  // k = 2 (shipped)
  complement_fourth_root,  // k = 4
  complement_eighth_root,  // k = 8
};

// What a texel stores.
enum class TableValues {
  raw,         // (c_2, c_3) (shipped)
  normalised,  // (c_2, c_3) / (1 - r), the normalised curve's coefficients
};

// Which solve fills the texels.
enum class TableSolve {
  basis,  // the basis' own (near-minimax for extended, probes for paper): what compiling does
  least_squares,  // smooth in (r, g), but further from the per-material compile
};

// 128: the study (docs/accuracy.md) finds it within 0.002 of the per-material compile on the
// issue's random and grid inputs for every basis; the powers basis' coefficients change fastest
// near r = 1, where 112 columns left 0.0021 (issue #28); 64 KiB in f16, 128 KiB in f32.
inline constexpr std::size_t kDefaultCoefficientTableSize = 128;
inline constexpr std::size_t kMinCoefficientTableSize = 2;
inline constexpr std::size_t kMaxCoefficientTableSize = 1024;

// At r = 0 (n = 1, no interface) the curve is 0 at every mu > 0 and its solve is nothing like the
// limit r -> 0+, which spoils the first cell of a table whose first cell is wide (sqrt(r) axes);
// the study can solve the first column this fraction of a texel in instead. With the shipped
// axis the first cell ends at r = 6e-8 and the column is solved at r = 0.
inline constexpr double kDefaultFirstColumnOffset = 0.0;

struct CoefficientTableOptions {
  std::size_t size = kDefaultCoefficientTableSize;
  ReflectivityAxis axis = ReflectivityAxis::fourth_root_plus_square;
  EdgeTintAxis edge_tint_axis = EdgeTintAxis::complement_square_root;
  TableValues values = TableValues::raw;
  TableSolve solve = TableSolve::basis;
  double first_column_offset = kDefaultFirstColumnOffset;  // in texels
  unsigned threads = 0;  // 0: one per hardware thread; the bytes do not depend on it
};

// An owning table of any layout; only the shipped layout can be viewed by the runtime.
struct CoefficientTable {
  CoefficientTableOptions options;
  runtime::BasisKind basis = runtime::kDefaultBasis;
  std::vector<float> texels;  // size * size * 2, rows by g

  std::size_t size() const { return options.size; }
  bool shipped_layout() const;
  // Throws std::logic_error for another layout.
  runtime::CoefficientTableView view() const;
};

// The reflectivity at (fractional) texel column x, and the edge tint of row y in that column.
double coefficient_table_column_reflectivity(const CoefficientTableOptions& options, double x);
double coefficient_table_row_edge_tint(const CoefficientTableOptions& options, double reflectivity,
                                       std::size_t y);

// Throws std::invalid_argument for a size outside [kMinCoefficientTableSize,
// kMaxCoefficientTableSize].
CoefficientTable fit_coefficient_table(runtime::BasisKind basis,
                                       const CoefficientTableOptions& options = {});

// The texels as RGBA (z = w = 0), for uploads that take four channels only (the Vulkan
// executor's RGBA32F images): .xy filter exactly as from an RG texture.
std::vector<float> rgba_texels(const CoefficientTable& table);

// One channel's c_0..c_3 read from a table of any layout, bilinearly filtered like a sampler
// (the shipped layout through the runtime's own function).
runtime::ChannelCoefficients channel_coefficients(const CoefficientTable& table,
                                                  double reflectivity, double edge_tint);

// The C++ source of runtime/src/generated/<basis>_coefficient_table.cpp (the shipped layout).
std::string coefficient_table_source(const CoefficientTable& table);

}  // namespace matc
