// What `matc bake` bakes: one textured metal's two maps (reflectivity and edge tint, or n and k),
// each an image file or a constant, read from a small JSON asset file (docs/baking.md) or built
// from command-line options. Parsing gives located diagnostics like material files.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "bake/image_map.h"
#include "base/diagnostics.h"
#include "matc/runtime/fresnel.h"

namespace matc {

enum class BakeModel { artistic, ior };

// Which quantity a map holds, with its allowed range.
enum class MapQuantity { reflectivity, edge_tint, n, k };
std::string_view map_quantity_field(MapQuantity quantity);  // "artistic.reflectivity", ...
std::string map_quantity_range(MapQuantity quantity);       // "[0, 1]", "(0, 1000]", ...
bool map_value_allowed(MapQuantity quantity, double value);

// One map: an image file or a constant (grey or R, G, B).
struct MapInput {
  MapQuantity quantity = MapQuantity::reflectivity;
  std::string file;                          // as written; empty for a constant
  std::filesystem::path resolved;            // against the asset file's folder
  MapEncoding encoding = MapEncoding::srgb;  // for 8- and 16-bit files
  bool encoding_given = false;               // said explicitly (an OpenEXR cannot be sRGB)
  std::optional<runtime::Rgb> constant;
  SourceLocation location;  // where it was given: a JSON value, or the command line
  bool is_file() const { return !constant.has_value(); }
};

struct BakeAsset {
  std::string name;         // the stem of every output file
  std::string source_path;  // the asset file; empty when built from the command line
  BakeModel model = BakeModel::artistic;
  MapInput first;   // reflectivity or n
  MapInput second;  // edge tint or k
  SourceLocation name_location;
};

struct BakeAssetResult {
  std::optional<BakeAsset> asset;  // set when there is no error
  Diagnostics diagnostics;
};

// Parses an asset file's JSON `text`; `path` names it and resolves relative map paths.
BakeAssetResult parse_bake_asset(std::string_view text, const std::string& path);
BakeAssetResult read_bake_asset_file(const std::string& path);

// The default encoding of a map file: sRGB for reflectivity and edge tint (colours), linear for
// n and k (physical data); OpenEXR files are linear whatever this says.
MapEncoding default_map_encoding(MapQuantity quantity);

}  // namespace matc
