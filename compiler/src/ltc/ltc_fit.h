// Fitting the LTC table for GGX (matc/runtime/ltc.h): per (NdotV, roughness) texel, the matrix
// whose transformed cosine best matches the GGX lobe normalised by its albedo, with Heitz et al.'s
// parametrisation M = [X Y Z] [[m11, 0, m13], [0, m22, 0], [0, 0, 1]], minimised by Nelder-Mead.
// Two departures from their fit, both measured in docs/ltc.md: the frame's angle
// (Z = (sin, 0, cos)) is a fourth free parameter rather than fixed at the lobe's average
// direction, and the shipped objective scores what is rendered, the LTC's integral over random
// quad lights against the lobe's (lobe_polygons.h), starting from the fit of the densities' L1
// distance (integrated with samples from both, balance heuristic) rather than their cubed
// difference. Rows (roughness) are independent and each sweeps from normal incidence to grazing,
// starting every texel from the one before, so the table is the same whatever the thread count.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ltc/lobe_polygons.h"
#include "matc/runtime/ltc.h"

namespace matc {

inline constexpr std::size_t kDefaultLtcSize = 64;
inline constexpr std::size_t kLtcFitSamplesPerAxis = 32;  // 32 x 32 points from each density

struct LtcShape {
  double m11 = 1.0;
  double m22 = 1.0;
  double m13 = 0.0;
  double angle = 0.0;  // of Z from the normal, towards +x
};

// What one texel's fit reached.
struct LtcCellFit {
  runtime::LtcInverse inverse;
  LtcShape shape;
  double cubed_distance = 0.0;  // integral of |D_ggx - D_ltc|^3 (Heitz et al.'s objective)
  double l1_distance = 0.0;     // integral of |D_ggx - D_ltc| over the sphere, in [0, 2]
};

// What Nelder-Mead minimises: the integral of |D_ggx - D_ltc| (l1) or of its cube (Heitz et
// al.'s, l3), or what a renderer sees (polygons): the mean error of the LTC's integral over
// kLtcTrainingPolygons random quads (lobe_polygons.h) relative to the albedo, from the l1 fit.
enum class LtcObjective { l1, l3, polygons };
inline constexpr std::array<LtcObjective, 3> kLtcObjectives = {LtcObjective::l1, LtcObjective::l3,
                                                               LtcObjective::polygons};
std::string_view ltc_objective_name(LtcObjective objective);  // "l1", "l3", "polygons"
inline constexpr std::size_t kLtcTrainingPolygons = 128;
inline constexpr std::size_t kLtcTrainingPolygonSamples = 2048;  // reference pairs per quad

// Two changes to the polygon objective that docs/ltc.md measured and did not keep: more training
// quads at grazing views (NdotV < kLtcGrazingNdotV), where the fit is weakest, and a term for the
// LTC's mass below the horizon (ltc_mass_below_horizon), what a light over the whole upper
// hemisphere misses, weighted against the quads' mean error.
inline constexpr double kLtcGrazingNdotV = 0.1;
struct LtcPolygonVariant {
  std::size_t grazing_polygons = kLtcTrainingPolygons;
  double horizon_weight = 0.0;
};

struct LtcFitOptions {
  std::size_t size = kDefaultLtcSize;
  unsigned threads = 0;  // 0: one per hardware thread
  LtcObjective objective = LtcObjective::polygons;
  // Where the columns lie (matc/runtime/ltc.h): the shaders sample the angular axis only; the
  // other is for the study in docs/ltc.md.
  runtime::LtcViewAxis view_axis = runtime::LtcViewAxis::angular;
  LtcPolygonVariant variant{};  // the shipped fit: the defaults
};

struct LtcTable {
  std::size_t size = 0;
  std::vector<float> texels;           // size * size * 4: (a, b, c, d) per texel, rows by roughness
  std::vector<double> cubed_distance;  // per texel
  std::vector<double> l1_distance;     // per texel
  runtime::LtcViewAxis view_axis = runtime::LtcViewAxis::angular;

  runtime::LtcTableView view() const { return {size, texels, view_axis}; }
};

// The texel's cosine (on the table's view axis) and roughness.
double ltc_texel_ndotv(std::size_t x, std::size_t size,
                       runtime::LtcViewAxis axis = runtime::LtcViewAxis::angular);
double ltc_texel_roughness(std::size_t y, std::size_t size);

// One texel, from a first guess (the previous texel of the row, or isotropic when `isotropic`).
LtcCellFit fit_ltc_cell(double ndotv, double roughness, const LtcShape& first_guess, bool isotropic,
                        LtcObjective objective = LtcObjective::l1,
                        const LtcPolygonVariant& variant = {});

// The LTC that fits one set of quads best, from `start`: their mean error, or their largest
// (minimax), with no bound on the L1 distance. Fitted to a texel's held-out quads it is what no
// table can beat on them, the floor docs/ltc.md measures the shipped fit against (Nelder-Mead
// restarted from its own result until it stops improving: a local search, so the floor found,
// not a proven one).
enum class PolygonSetAggregate { mean, max };
LtcCellFit fit_ltc_to_polygons(const runtime::LtcInverse& start, double ndotv, double roughness,
                               std::span<const LobePolygon> polygons,
                               PolygonSetAggregate aggregate);

// The distances of a given LTC (a texel as a file stores it) from the GGX lobe, measured like the
// fit measures them.
LtcCellFit evaluate_ltc_cell(const runtime::LtcInverse& inverse, double ndotv, double roughness);

// Rows [first_row, first_row + row_count) of a table of `options.size` (the rest left zero):
// the whole table by default. Throws std::invalid_argument for a size outside [2, 1024].
LtcTable fit_ltc_table(const LtcFitOptions& options, std::size_t first_row = 0,
                       std::size_t row_count = static_cast<std::size_t>(-1));

// The share of an LTC's distribution below the shading horizon, which its integral clips: under
// a light over the whole upper hemisphere the LTC gives E (1 - this) where the lobe gives E. The
// horizon z = 0 is, in the cosine's space, the plane normal to (-c, 0, a), and a clamped cosine
// has (1 + n.z) / 2 of its mass on the side n points to.
double ltc_mass_below_horizon(const runtime::LtcInverse& inverse);

// The polygon-light error of each texel of a table: for squares seen towards the mirror
// direction, the normal and the horizon (one crossing it), the largest |E I_ltc(P) -
// integral over P of f cos| relative to the albedo E, the integral estimated with `samples` pairs
// (area_light_reference.h).
std::vector<double> ltc_polygon_errors(const runtime::LtcTableView& table, std::size_t samples,
                                       unsigned threads = 0);

// The C++ source of runtime/src/generated/ltc_table.cpp for this table.
std::string ltc_table_source(const LtcTable& table);

}  // namespace matc
