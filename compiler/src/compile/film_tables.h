// Baking a filmed metal's own tables (runtime/film_table.h, issue #67) from its exact curve. The
// sizes are those docs/accuracy.md measured ("A film's curve as a table", "A film's image light"):
// F within 0.0026 and Fbar within 0.0041 of the exact film's over the measured metals and films of
// 0-1000 nm; FilmTables.* holds them on a few.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include "matc/runtime/film_table.h"
#include "material/material.h"
#include "optics/reflectance_curve.h"
#include "optics/thin_film.h"

namespace matc {

// GGX samples a node of a film table's Fbar rows (see bake_film_table).
inline constexpr std::size_t kFilmTableSamples = 512;

// The tables of `curve` (a filmed metal's exact curve): F at the cosine nodes, and each Fbar node
// a split sum of the F table (read as the shaders read it) over `samples` GGX visible normals, as
// matc's own table is baked. 512 hold FilmTables.* as 1,024 do (the nodes' spacing, not the
// samples, sets the error: 0.0034 against 0.0035 on gold under 800 nm) at half the bake. In double
// precision: the file rounds it (lut/film_table_files.h).
runtime::FilmTable bake_film_table(const ReflectanceCurve& curve,
                                   std::size_t samples = kFilmTableSamples);

// A film under a coat (docs/thin-film.md): the table of the base lobe. F is the exact layered base
// (LayeredCurve's base part) at the cosine nodes; each Fbar node layers the split sums of the film
// in air's and under the coat's F tables (read as the shaders read them) with the coat's split sum
// at its own roughness and its tint at NdotV, as runtime::layered_base layers a coated metal's
// preintegrated basis, and as lut/layered_reference.h's layered_split_sum does with exact curves.
// `in_air` is unused under a full coat, which leaves nothing of the metal in air.
runtime::FilmTable bake_coated_film_table(const ReflectanceCurve& in_air,
                                          const ReflectanceCurve& under_coat, const CoatInput& coat,
                                          std::size_t samples = kFilmTableSamples);

// A thickness per pixel (docs/thin-film.md "A thickness per pixel"): the tables of films
// uniform over [minimum_nm, maximum_nm], read linearly over the thickness between them. The
// spacing starts at kFilmStackFirstSpacingNm and halves (the midpoints measured become nodes)
// until linear interpolation over the thickness holds F within kFilmStackTarget at every midpoint
// and cosine node from 0.05, or the next halving would pass kMaxFilmStackSlices.
inline constexpr double kFilmStackFirstSpacingNm = 20.0;
inline constexpr double kFilmStackTarget = 0.005;
// 18 rows a slice: 227 slices are 4,086 rows, within the 4,096 texels a side every Vulkan device
// and WebGL2 implementation offers.
inline constexpr std::size_t kMaxFilmStackSlices = 227;

struct BakedFilmStack {
  runtime::FilmStack stack;
  // The largest |F - exact| at the thickness midpoints between slices (cosine nodes from 0.05,
  // channels): the thickness axis' error, beside each slice's own over the cosine.
  double thickness_error = 0.0;
};

// A film's F at the cosine nodes (runtime::film_table_cosine), at thicknesses start_nm + k step_nm
// for k < count: what a stack tabulates.
using FilmFresnelRow = std::array<Rgb, runtime::FilmTable::kCosineNodes>;
using FilmRows =
    std::function<std::vector<FilmFresnelRow>(double start_nm, double step_nm, std::size_t count)>;

// Rows from `sweep` (a film curve's ThinFilmSweep: amplitudes once a cosine, phases turned a step
// at a time), a cosine a thread.
FilmRows film_rows_by_sweep(const ThinFilmSweep& sweep);
// Rows from a curve per thickness, `film_at(nm)` (any film, a gamut-mapped one say), a thickness
// a thread: film_at is called from several threads at once.
FilmRows film_rows_by_curve(std::function<std::unique_ptr<ReflectanceCurve>(double)> film_at);

BakedFilmStack bake_film_stack(const FilmRows& rows, double minimum_nm, double maximum_nm,
                               std::size_t samples = kFilmTableSamples);

}  // namespace matc
