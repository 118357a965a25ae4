// A filmed metal's table (runtime/film_table.h) as the file <name>.film.<ext> an engine loads
// beside the shared tables: KTX2, DDS, raw texels or a C++ header, in the preintegrated table's
// format and precision (docs/thin-film.md).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "formats/table_format.h"
#include "matc/runtime/film_table.h"

namespace matc {

// The table as a file of this precision stores it, so CPU evaluation reads what a renderer samples:
// f16 rounds each value through half. f32 keeps the doubles: their rounding to float (below 6e-8)
// is left out, so that every build of the library, the WebAssembly one among them, gives the same
// values to the last digits (a float rounding can tip either way between two of them).
runtime::FilmTable stored_as(runtime::FilmTable table, LutPrecision precision);

// Its texels as the file holds them (runtime::film_table_texels of stored_as): what a renderer
// uploads.
std::vector<float> stored_film_texels(const runtime::FilmTable& table, LutPrecision precision);

// The file's bytes: stored_film_texels at `precision`; the header format names its arrays after
// `material_name`.
std::string encode_film_table(const runtime::FilmTable& table, LutFormat format,
                              LutPrecision precision, std::string_view material_name);

// The same for a thickness per pixel: every slice stored so, and the stack's texture
// (runtime::film_stack_texels).
runtime::FilmStack stored_as(runtime::FilmStack stack, LutPrecision precision);
std::vector<float> stored_film_texels(const runtime::FilmStack& stack, LutPrecision precision);
std::string encode_film_table(const runtime::FilmStack& stack, LutFormat format,
                              LutPrecision precision, std::string_view material_name);

// "<name>.film.<ext>" (a material's name has no dot: it clashes with no other file).
// What sits between a filmed metal's name and its table's extension (<name>.film.ktx2); the
// generated build-system layouts declare it from here too (emit/output_layout.cpp).
inline constexpr std::string_view kFilmTableInfix = ".film";

std::string film_table_file_name(std::string_view material_name, LutFormat format);

}  // namespace matc
