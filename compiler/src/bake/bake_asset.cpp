#include "bake/bake_asset.h"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "base/echoed_text.h"
#include "material/located_json_reader.h"
#include "material/material.h"
#include "material/parse.h"
#include "optics/spectrum.h"

namespace matc {
namespace {

using nlohmann::json;

constexpr std::array<std::string_view, 4> kTopLevelFields = {"$schema", "name", "artistic", "ior"};
constexpr std::array<std::string_view, 2> kArtisticFields = {"reflectivity", "edge_tint"};
constexpr std::array<std::string_view, 2> kIorFields = {"n", "k"};
constexpr std::array<std::string_view, 2> kMapFields = {"file", "encoding"};

Range quantity_range(MapQuantity quantity) {
  switch (quantity) {
    case MapQuantity::reflectivity:
    case MapQuantity::edge_tint:
      return {0.0, 1.0};
    case MapQuantity::n:
    case MapQuantity::k:
      break;
  }
  return {0.0, kMaxIorComponent};
}

class BakeAssetReader : LocatedJsonReader {
 public:
  BakeAssetReader(const LocatedJson& document, const TextLocator& locator, Diagnostics& diagnostics,
                  std::filesystem::path base_directory)
      : LocatedJsonReader(document, locator, diagnostics),
        base_directory_(std::move(base_directory)) {}

  std::optional<BakeAsset> read() {
    report_duplicate_keys();
    const json& root = document_.value;
    const std::string allowed = "a JSON object with the fields name and one of artistic, ior";
    if (!root.is_object()) {
      error("", fmt::format("the file holds {}", describe_type(root)), allowed);
      return std::nullopt;
    }
    warn_unknown_fields(root, "", kTopLevelFields);
    BakeAsset asset;
    asset.source_path = locator_.path();
    if (auto name = read_name(root)) {
      asset.name = std::move(*name);
      asset.name_location = at_value("/name");
    }
    if (root.contains("$schema") && !root["$schema"].is_string())
      error("/$schema", fmt::format("is {}", describe_type(root["$schema"])), "a string");
    const bool artistic = root.contains("artistic"), ior = root.contains("ior");
    if (artistic == ior) {
      diagnostics_.error(at_value(""), "",
                         artistic ? "gives both artistic and ior maps" : "gives no maps",
                         "exactly one of artistic (reflectivity, edge_tint) or ior (n, k)");
    } else if (artistic) {
      asset.model = BakeModel::artistic;
      read_pair(root, "artistic", kArtisticFields, MapQuantity::reflectivity,
                MapQuantity::edge_tint, asset);
    } else {
      asset.model = BakeModel::ior;
      read_pair(root, "ior", kIorFields, MapQuantity::n, MapQuantity::k, asset);
    }
    if (diagnostics_.has_errors()) return std::nullopt;
    return asset;
  }

 private:
  void read_pair(const json& root, std::string_view key, std::span<const std::string_view> fields,
                 MapQuantity first_quantity, MapQuantity second_quantity, BakeAsset& asset) {
    const json* object = object_field(root, key, fields);
    if (!object) return;
    const std::string pointer = child("", key);
    read_map(*object, pointer, fields[0], first_quantity, asset.first);
    read_map(*object, pointer, fields[1], second_quantity, asset.second);
  }

  // A map: "file.png", {"file": ..., "encoding": ...}, or a constant (number or [R, G, B]).
  void read_map(const json& object, const std::string& parent, std::string_view key,
                MapQuantity quantity, MapInput& map) {
    const Range range = quantity_range(quantity);
    const std::string allowed = fmt::format(
        "an image path (PNG, JPEG or OpenEXR, relative to this file), {{\"file\": path, "
        "\"encoding\": \"srgb\" or \"linear\"}}, or a constant in {} (grey or [R, G, B])",
        range.describe());
    map.quantity = quantity;
    map.encoding = default_map_encoding(quantity);
    if (!object.contains(key)) {
      missing(parent, key, allowed);
      return;
    }
    const std::string pointer = child(parent, key);
    const json& value = object[std::string(key)];
    map.location = at_value(pointer);
    if (value.is_number() || value.is_array()) {
      map.constant = read_rgb(value, pointer, range);
      if (!map.constant) return;
      if (quantity == MapQuantity::n) {
        for (double component : *map.constant)
          if (component == 0.0) error(pointer, "n = 0 is not a material", "n > 0");
      }
      return;
    }
    const json* file = &value;
    std::string file_pointer = pointer;
    if (value.is_object()) {
      warn_unknown_fields(value, pointer, kMapFields);
      if (!value.contains("file")) {
        missing(pointer, "file", "an image path relative to this file");
        return;
      }
      file = &value["file"];
      file_pointer = child(pointer, "file");
      if (value.contains("encoding")) {
        const json& encoding = value["encoding"];
        const auto parsed = encoding.is_string()
                                ? map_encoding_from_name(encoding.get<std::string>())
                                : std::nullopt;
        if (!parsed) {
          error(child(pointer, "encoding"),
                encoding.is_string()
                    ? fmt::format("unknown encoding '{}'", echoed(encoding.get<std::string>()))
                    : fmt::format("is {}", describe_type(encoding)),
                "\"srgb\" (colour maps, the default for reflectivity and edge tint) or "
                "\"linear\" (data maps, the default for n and k)");
          return;
        }
        map.encoding = *parsed;
        map.encoding_given = true;
      }
    } else if (!value.is_string()) {
      error(pointer, fmt::format("is {}", describe_type(value)), allowed);
      return;
    }
    if (!file->is_string() || file->get<std::string>().empty()) {
      error(file_pointer,
            file->is_string() ? "is empty" : fmt::format("is {}", describe_type(*file)), allowed);
      return;
    }
    map.file = file->get<std::string>();
    map.resolved = (base_directory_ / map.file).lexically_normal();
    map.location = at_value(file_pointer);
  }

  std::filesystem::path base_directory_;
};

}  // namespace

std::string_view map_quantity_field(MapQuantity quantity) {
  switch (quantity) {
    case MapQuantity::reflectivity:
      return "artistic.reflectivity";
    case MapQuantity::edge_tint:
      return "artistic.edge_tint";
    case MapQuantity::n:
      return "ior.n";
    case MapQuantity::k:
      break;
  }
  return "ior.k";
}

std::string map_quantity_range(MapQuantity quantity) {
  if (quantity == MapQuantity::n) return fmt::format("(0, {}]", kMaxIorComponent);
  return quantity_range(quantity).describe();
}

bool map_value_allowed(MapQuantity quantity, double value) {
  if (!std::isfinite(value)) return false;
  if (quantity == MapQuantity::n && value <= 0.0) return false;
  return quantity_range(quantity).contains(value);
}

MapEncoding default_map_encoding(MapQuantity quantity) {
  return quantity == MapQuantity::reflectivity || quantity == MapQuantity::edge_tint
             ? MapEncoding::srgb
             : MapEncoding::linear;
}

BakeAssetResult parse_bake_asset(std::string_view text, const std::string& path) {
  BakeAssetResult result;
  const TextLocator locator(path, text);
  const auto document = parse_located_json_reporting(text, locator, result.diagnostics);
  if (!document) return result;
  BakeAssetReader reader(*document, locator, result.diagnostics,
                         std::filesystem::path(path).parent_path());
  result.asset = reader.read();
  return result;
}

BakeAssetResult read_bake_asset_file(const std::string& path) {
  const LoadedFile loaded = load_file(path, kMaxMaterialFileBytes);
  if (!loaded.bytes) {
    BakeAssetResult result;
    result.diagnostics.error({path, 0, 0}, "", fmt::format("cannot read: {}", loaded.error),
                             "a bake asset JSON file of at most 1 MiB");
    return result;
  }
  return parse_bake_asset(*loaded.bytes, path);
}

}  // namespace matc
