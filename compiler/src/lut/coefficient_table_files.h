// The coefficient table as files an engine loads, in the preintegrated table's formats (KTX2, DDS,
// raw texels or a C++ header) and precisions, with a JSON manifest (docs/coefficient-table.md).
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "fit/coefficient_table.h"
#include "lut/lut_files.h"

namespace matc {

// The table as a file of this precision stores it (rounded through half for f16).
CoefficientTable stored_as(CoefficientTable table, LutPrecision precision);

// The table checked in for a shipped basis (runtime::shipped_coefficient_table), as a file of
// this precision stores it: what `matc` writes and what a shader samples.
CoefficientTable stored_coefficient_table(runtime::BasisKind basis, LutPrecision precision);

// The file's bytes: an RG float texture (KTX2 VK_FORMAT_R{16,32}G{16,32}_SFLOAT, DDS
// DXGI_FORMAT_R{16,32}G{16,32}_FLOAT), raw texels, or a C++ header. Shipped layout only.
std::string encode_coefficient_table(const CoefficientTable& table, LutFormat format,
                                     LutPrecision precision);

// Axes, texel convention, what the channels hold and how a shader reconstructs c_0..c_3.
nlohmann::ordered_json coefficient_table_manifest(const CoefficientTable& table, LutFormat format,
                                                  LutPrecision precision);

}  // namespace matc
