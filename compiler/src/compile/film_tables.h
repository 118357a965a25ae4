// Baking a filmed metal's own tables (runtime/film_table.h, issue #67) from its exact curve. The
// sizes are those docs/accuracy.md measured ("A film's curve as a table", "A film's image light"):
// F within 0.0026 and Fbar within 0.0041 of the exact film's over the measured metals and films of
// 0-1000 nm; FilmTables.* holds them on a few.
#pragma once

#include <cstddef>

#include "matc/runtime/film_table.h"
#include "optics/reflectance_curve.h"

namespace matc {

// The tables of `curve` (a filmed metal's exact curve): F at the cosine nodes, and each Fbar node
// a split sum of the F table (read as the shaders read it) over `samples` GGX visible normals, as
// matc's own table is baked. 512 hold FilmTables.* as 1,024 do (the nodes' spacing, not the
// samples, sets the error: 0.0034 against 0.0035 on gold under 800 nm) at half the bake. In double
// precision: the file rounds it (lut/film_table_files.h).
runtime::FilmTable bake_film_table(const ReflectanceCurve& curve, std::size_t samples = 512);

}  // namespace matc
