// Baking a filmed metal's own tables (runtime/film_table.h, issue #67) from its exact curve. The
// sizes are those docs/accuracy.md measured ("A film's curve as a table", "A film's image light"):
// F within 0.0026 and Fbar within 0.0041 of the exact film's over the measured metals and films of
// 0-1000 nm; FilmTables.* holds them on a few.
#pragma once

#include <cstddef>

#include "matc/runtime/film_table.h"
#include "material/material.h"
#include "optics/reflectance_curve.h"

namespace matc {

// The tables of `curve` (a filmed metal's exact curve): F at the cosine nodes, and each Fbar node
// a split sum of the F table (read as the shaders read it) over `samples` GGX visible normals, as
// matc's own table is baked. 512 hold FilmTables.* as 1,024 do (the nodes' spacing, not the
// samples, sets the error: 0.0034 against 0.0035 on gold under 800 nm) at half the bake. In double
// precision: the file rounds it (lut/film_table_files.h).
runtime::FilmTable bake_film_table(const ReflectanceCurve& curve, std::size_t samples = 512);

// A film under a coat (docs/thin-film.md): the table of the base lobe. F is the exact layered base
// (LayeredCurve's base part) at the cosine nodes; each Fbar node layers the split sums of the film
// in air's and under the coat's F tables (read as the shaders read them) with the coat's split sum
// at its own roughness and its tint at NdotV, as runtime::layered_base layers a coated metal's
// preintegrated basis, and as lut/layered_reference.h's layered_split_sum does with exact curves.
// `in_air` is unused under a full coat, which leaves nothing of the metal in air.
runtime::FilmTable bake_coated_film_table(const ReflectanceCurve& in_air,
                                          const ReflectanceCurve& under_coat, const CoatInput& coat,
                                          std::size_t samples = 512);

}  // namespace matc
