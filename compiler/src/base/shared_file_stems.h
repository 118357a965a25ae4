// The stems of the files every build writes once: the shared library, the tables and the
// manifest (matc_fresnel.*, matc_lut.*, ...). A material of one of these names, in any case,
// would write its files over them: the compile refuses such a name in a material file, and the
// glTF importer, whose names need not be unique, derives another. Here, below both; the output
// layout (emit/output_layout.h) is checked against it (OutputLayout.SharedStemsAreTheBaseList).
#pragma once

#include <array>
#include <string_view>

namespace matc {

inline constexpr std::array<std::string_view, 5> kSharedFileStems = {
    "matc_fresnel", "matc_lut", "matc_coefficient_table", "matc_ltc", "matc_manifest"};

}  // namespace matc
