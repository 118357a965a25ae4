// The LTC table as files an engine loads, in the other tables' formats (KTX2, DDS, raw texels or a
// C++ header), always 32-bit float: the roughness-0 row holds entries far below half precision's
// range. With a JSON manifest (docs/ltc.md).
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "lut/lut_files.h"
#include "matc/runtime/ltc.h"

namespace matc {

// The file's bytes: an RGBA float texture (KTX2 VK_FORMAT_R32G32B32A32_SFLOAT, DDS
// DXGI_FORMAT_R32G32B32A32_FLOAT), raw texels, or a C++ header.
std::string encode_ltc_table(const runtime::LtcTableView& table, LutFormat format);

// Axes, texel convention, what the channels hold and how a shader uses them.
nlohmann::ordered_json ltc_table_manifest(const runtime::LtcTableView& table, LutFormat format);

}  // namespace matc
