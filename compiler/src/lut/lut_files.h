// The LUT as files an engine loads: KTX2, DDS, raw texels or a C++ header, plus a JSON manifest.
// Layouts are described in docs/lut.md.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/output_file.h"
#include "formats/table_format.h"
#include "lut/lut_atlas.h"
#include "lut/preintegrate.h"

namespace matc {

// A baked table with its energy-compensation companions.
struct BakedLut {
  Lut lut;
  std::vector<double> average_albedo;                        // E_avg per roughness row
  std::array<double, runtime::kBasisSize> basis_averages{};  // m_i
  runtime::BasisKind basis = runtime::kDefaultBasis;         // which basis was integrated
};

BakedLut bake_lut(const runtime::BasisView& basis, const LutOptions& options);
// The same for several bases at once (preintegrate_luts: the GGX samples shared), and for
// shipped bases by kind.
std::vector<BakedLut> bake_luts(std::span<const runtime::BasisView> bases,
                                const LutOptions& options);
std::vector<BakedLut> bake_luts(std::span<const runtime::BasisKind> bases,
                                const LutOptions& options);

// The table as a file of this precision stores it (texels rounded through half for f16), so CPU
// evaluation can sample exactly what a renderer loads.
Lut stored_as(Lut lut, LutPrecision precision);

// The file's bytes. The header format embeds the texels as C++ constexpr arrays (rounded through
// half precision when `precision` is f16, so they equal what the texture formats store).
std::string encode_lut(const BakedLut& baked, LutFormat format, LutPrecision precision);

// The table as the file `file_name` and its manifest `file_name` + ".json", bytes in memory.
std::vector<OutputFile> lut_output_files(const BakedLut& baked, LutFormat format,
                                         LutPrecision precision, std::string_view file_name);

// A layered table (--basis auto: lut_atlas.h): the file's bytes in `format` and its manifest,
// which names each layer's basis and columns. `atlas` holds the layers as stored (stored_as),
// `layers` their bakes in the same order.
std::string encode_layered_lut(std::span<const BakedLut> layers, const LutAtlas& atlas,
                               LutFormat format, LutPrecision precision);
nlohmann::ordered_json layered_lut_manifest(std::span<const BakedLut> layers, const LutAtlas& atlas,
                                            LutFormat format, LutPrecision precision);
// The "layout" of a manifest for a square table with rows roughness and columns
// u = `columns_from_ndotv` (the LUT's sqrt(NdotV), the LTC table's 1 - sqrt(1 - NdotV)), with
// `channels` floats per texel.
nlohmann::ordered_json roughness_table_layout(std::string_view columns_from_ndotv,
                                              std::string_view channels);

// What a renderer needs besides the texels: axes, texel-centre convention, energy tables.
nlohmann::ordered_json lut_manifest(const BakedLut& baked, LutFormat format,
                                    LutPrecision precision);

}  // namespace matc
