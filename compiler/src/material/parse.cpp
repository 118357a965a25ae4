#include "material/parse.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "base/echoed_text.h"
#include "base/identifier_names.h"
#include "located_json_reader.h"
#include "material/basis_pin.h"
#include "material/located_json.h"
#include "optics/presets.h"
#include "suggestion.h"

namespace matc {
namespace {

using nlohmann::json;
using runtime::Rgb;

constexpr std::array<std::string_view, 4> kModelKeys = {"artistic", "ior", "spectral", "f82_tint"};
constexpr std::string_view kOneModel = "exactly one of artistic, ior, spectral, f82_tint";
constexpr std::array<std::string_view, 12> kTopLevelFields = {
    "$schema",  "name",      "description", "artistic", "ior",  "spectral",
    "f82_tint", "roughness", "color_space", "coat",     "film", "basis"};
constexpr std::array<std::string_view, 2> kF82TintFields = {"f0", "tint"};
constexpr std::array<std::string_view, 2> kArtisticFields = {"reflectivity", "edge_tint"};
constexpr std::array<std::string_view, 2> kIorFields = {"n", "k"};
constexpr std::array<std::string_view, 2> kSpectralFields = {"preset", "file"};
constexpr std::array<std::string_view, 4> kCoatFields = {"weight", "ior", "roughness", "color"};
constexpr std::array<std::string_view, 3> kFilmFields = {"weight", "ior", "thickness"};

constexpr Range kReflectivityRange{0.0, 1.0, false};
constexpr Range kUnitRange{0.0, 1.0};
constexpr Range kIorRange{0.0, kMaxIorComponent};
// OpenPBR's coat_ior range, 1 (no interface) to 3, from 1.05: nearer 1 the coat's Fresnel is a
// spike at grazing that no basis made for Fresnel curves holds (docs/coating.md).
constexpr Range kCoatIorRange{kMinCoatIor, 3.0};
// A film's index from 1 (no film) to OpenPBR's 3; thickness up to 2 micrometres, past the
// thickest anodised or tempered films (about 1 micrometre) and well past where the fringes blur.
constexpr Range kFilmIorRange{kMinFilmIor, kMaxFilmIor};
constexpr Range kFilmThicknessRange{0.0, kMaxFilmThicknessNm};

class MaterialReader : LocatedJsonReader {
 public:
  MaterialReader(const LocatedJson& document, const TextLocator& locator, Diagnostics& diagnostics,
                 const FileLoader& loader, std::filesystem::path base_directory)
      : LocatedJsonReader(document, locator, diagnostics),
        loader_(loader),
        base_directory_(std::move(base_directory)) {}

  std::optional<Material> read() {
    report_duplicate_keys();
    const json& root = document_.value;
    if (!root.is_object()) {
      error("", fmt::format("the file holds {}", describe_type(root)),
            "a JSON object with the fields name and one of artistic, ior, spectral, f82_tint");
      return std::nullopt;
    }
    warn_unknown_fields(root, "", kTopLevelFields);

    Material material;
    material.source_path = locator_.path();
    if (auto name = read_name(root)) {
      material.name = std::move(*name);
      material.name_location = at_value("/name");
    }
    if (root.contains("roughness")) {
      material.roughness = read_number(root["roughness"], "/roughness", kUnitRange);
    }
    if (root.contains("description") && !root["description"].is_string()) {
      error("/description", fmt::format("is {}", describe_type(root["description"])), "a string");
    }
    if (root.contains("$schema") && !root["$schema"].is_string()) {
      error("/$schema", fmt::format("is {}", describe_type(root["$schema"])), "a string");
    }
    if (root.contains("color_space")) material.color_space = read_color_space(root["color_space"]);
    if (auto model = read_model(root)) material.model = std::move(*model);
    if (root.contains("coat")) material.coat = read_coat(root);
    if (root.contains("film")) material.film = read_film(root);
    if (root.contains("basis")) material.basis = read_basis(root);

    if (diagnostics_.has_errors()) return std::nullopt;
    return material;
  }

 private:
  std::optional<MaterialModel> read_model(const json& root) {
    std::vector<std::string_view> given;
    for (const std::string_view key : kModelKeys) {
      if (root.contains(key)) given.push_back(key);
    }
    if (given.empty()) {
      diagnostics_.error(at_value(""), "", "no material model is given", std::string(kOneModel));
      return std::nullopt;
    }
    if (given.size() > 1) {
      std::sort(given.begin(), given.end(), [&](std::string_view a, std::string_view b) {
        return document_.key_or_value_offset(child("", a)) <
               document_.key_or_value_offset(child("", b));
      });
      for (std::size_t i = 1; i < given.size(); ++i) {
        diagnostics_.error(at_key(child("", given[i])), std::string(given[i]),
                           fmt::format("a second material model ('{}' is given at {})", given[0],
                                       where(document_.key_or_value_offset(child("", given[0])))),
                           std::string(kOneModel));
      }
    }
    // Each model given is still checked, so that one run reports every problem in the file.
    std::optional<MaterialModel> model;
    for (const std::string_view key : given)
      model = read_model(root, key);
    if (given.size() > 1) return std::nullopt;
    return model;
  }

  std::optional<MaterialModel> read_model(const json& root, std::string_view key) {
    if (key == "artistic") return read_artistic(root);
    if (key == "ior") return read_ior(root);
    if (key == "f82_tint") return read_f82_tint(root);
    return read_spectral(root);
  }

  std::optional<MaterialModel> read_f82_tint(const json& root) {
    const json* object = object_field(root, "f82_tint", kF82TintFields);
    if (!object) return std::nullopt;
    const auto f0 = read_rgb_field(*object, "/f82_tint", "f0", kUnitRange);
    const auto tint = read_rgb_field(*object, "/f82_tint", "tint", kUnitRange);
    if (!f0 || !tint) return std::nullopt;
    return F82TintInput{*f0, *tint};
  }

  // A block's number field, where given: range-checked into `into`; `ok` turns false on an error.
  void read_block_number(const json& object, const std::string& block, std::string_view key,
                         const Range& range, double& into, bool& ok) {
    if (!object.contains(key)) return;
    const auto value = read_number(object[std::string(key)], child(block, key), range);
    if (value) into = *value;
    ok = ok && value.has_value();
  }

  // Every field is optional (CoatInput's defaults); each given one is range-checked.
  std::optional<CoatInput> read_coat(const json& root) {
    const json* object = object_field(root, "coat", kCoatFields);
    if (!object) return std::nullopt;
    CoatInput coat;
    bool ok = true;
    read_block_number(*object, "/coat", "weight", kUnitRange, coat.weight, ok);
    read_block_number(*object, "/coat", "ior", kCoatIorRange, coat.ior, ok);
    read_block_number(*object, "/coat", "roughness", kUnitRange, coat.roughness, ok);
    if (object->contains("color")) {
      const auto color = read_rgb((*object)["color"], "/coat/color", kUnitRange);
      if (color) coat.color = *color;
      ok = ok && color.has_value();
    }
    if (!ok) return std::nullopt;
    return coat;
  }

  // `thickness` is required (a film has no default thickness); weight and ior take FilmInput's
  // defaults.
  std::optional<FilmInput> read_film(const json& root) {
    const json* object = object_field(root, "film", kFilmFields);
    if (!object) return std::nullopt;
    FilmInput film;
    bool ok = true;
    read_block_number(*object, "/film", "weight", kUnitRange, film.weight, ok);
    read_block_number(*object, "/film", "ior", kFilmIorRange, film.ior, ok);
    if (!object->contains("thickness")) {
      missing("/film", "thickness", thickness_rule());
      ok = false;
    } else if (!read_film_thickness((*object)["thickness"], film)) {
      ok = false;
    }
    if (ok && film.thickness_minimum_nm && root.contains("coat")) {
      error(
          "/film/thickness", "is a range under a coat",
          "one thickness under a coat (a thickness per pixel is compiled over a bare metal only)");
      ok = false;
    }
    if (!ok) return std::nullopt;
    return film;
  }

  static std::string thickness_rule() {
    return fmt::format(
        "the film's thickness in nanometres, a number in {0}, or for a thickness per pixel "
        "{{\"minimum\": a, \"maximum\": b}} with a < b in {0}",
        kFilmThicknessRange.describe());
  }

  // A number, or a range {minimum, maximum} for a thickness texture (docs/thin-film.md).
  bool read_film_thickness(const json& value, FilmInput& film) {
    const std::string pointer = "/film/thickness";
    if (!value.is_object()) {
      if (!value.is_number()) {
        error(pointer, fmt::format("is {}", describe_type(value)), thickness_rule());
        return false;
      }
      const auto nm = read_number(value, pointer, kFilmThicknessRange);
      if (nm) film.thickness_nm = *nm;
      return nm.has_value();
    }
    static constexpr std::array<std::string_view, 2> kRangeFields = {"minimum", "maximum"};
    warn_unknown_fields(value, pointer, kRangeFields);
    bool ok = true;
    std::array<std::optional<double>, 2> ends;
    for (std::size_t e = 0; e < 2; ++e) {
      const std::string_view key = kRangeFields[e];
      if (!value.contains(key)) {
        missing(pointer, key,
                fmt::format("the {} thickness of the texture's range in nanometres, a number in {}",
                            key, kFilmThicknessRange.describe()));
        ok = false;
        continue;
      }
      ends[e] = read_number(value[std::string(key)], child(pointer, key), kFilmThicknessRange);
      ok = ok && ends[e].has_value();
    }
    if (!ok) return false;
    if (!(*ends[0] < *ends[1])) {
      error(child(pointer, "minimum"), fmt::format("is not below the maximum ({} nm)", *ends[1]),
            "a minimum below the maximum (one thickness is a number)");
      return false;
    }
    film.thickness_minimum_nm = *ends[0];
    film.thickness_nm = *ends[1];
    return true;
  }

  // A pinned basis (material/basis_pin.h).
  std::optional<runtime::BasisKind> read_basis(const json& root) {
    const std::string pointer = "/basis";
    const json& value = root["basis"];
    if (!value.is_string()) {
      error(pointer, fmt::format("is {}", describe_type(value)), basis_pin_rule());
      return std::nullopt;
    }
    const std::string_view layered = root.contains("coat")   ? "coat"
                                     : root.contains("film") ? "film"
                                                             : "";
    const BasisPin pin = read_basis_pin(value.get<std::string>(), layered);
    if (pin.problem) error(pointer, pin.problem->problem, pin.problem->allowed);
    return pin.basis;
  }

  std::optional<ColorSpace> read_color_space(const json& value) {
    const std::string pointer = "/color_space";
    const std::string allowed =
        fmt::format("one of {} (the space this file's RGB values are in)", color_space_names());
    if (!value.is_string()) {
      error(pointer, fmt::format("is {}", describe_type(value)), allowed);
      return std::nullopt;
    }
    const std::string name = value.get<std::string>();
    if (const auto space = find_color_space(name)) return space;
    if (is_encoded_color_space(name)) {
      error(pointer,
            fmt::format("'{}' is an encoded (non-linear) space; material values are linear "
                        "reflectances: decode them, then name the linear space",
                        echoed(name)),
            allowed);
      return std::nullopt;
    }
    std::vector<std::string_view> names;
    for (const auto& definition : color_spaces())
      names.push_back(definition.name);
    const auto suggestion = closest_match(name, names);
    error(pointer,
          suggestion ? fmt::format("unknown colour space '{}' (did you mean '{}'?)", echoed(name),
                                   *suggestion)
                     : fmt::format("unknown colour space '{}'", echoed(name)),
          allowed);
    return std::nullopt;
  }

  std::optional<MaterialModel> read_artistic(const json& root) {
    const json* object = object_field(root, "artistic", kArtisticFields);
    if (!object) return std::nullopt;
    const auto r = read_rgb_field(*object, "/artistic", "reflectivity", kReflectivityRange);
    const auto g = read_rgb_field(*object, "/artistic", "edge_tint", kUnitRange);
    if (!r || !g) return std::nullopt;
    return ArtisticInput{*r, *g};
  }

  std::optional<MaterialModel> read_ior(const json& root) {
    const json* object = object_field(root, "ior", kIorFields);
    if (!object) return std::nullopt;
    const auto n = read_rgb_field(*object, "/ior", "n", kIorRange);
    const auto k = read_rgb_field(*object, "/ior", "k", kIorRange);
    if (!n || !k) return std::nullopt;
    bool ok = true;
    for (std::size_t c = 0; c < 3; ++c) {
      if ((*n)[c] == 0.0 && (*k)[c] == 0.0) {
        const json& n_value = (*object)["n"];
        error(n_value.is_array() ? "/ior/n/" + std::to_string(c) : "/ior/n",
              fmt::format("n = k = 0 in the {} channel is not a material", "RGB"[c]),
              "n > 0 or k > 0 in every channel");
        ok = false;
      }
    }
    if (!ok) return std::nullopt;
    return IorInput{*n, *k};
  }

  std::optional<MaterialModel> read_spectral(const json& root) {
    const json* object = object_field(root, "spectral", kSpectralFields);
    if (!object) return std::nullopt;
    const bool has_preset = object->contains("preset");
    const bool has_file = object->contains("file");
    if (has_preset == has_file) {
      error("/spectral",
            has_preset ? "gives both preset and file" : "gives neither preset nor file",
            "exactly one of preset (a metal symbol such as \"Au\") or file (a CSV path)");
      return std::nullopt;
    }
    return has_preset ? read_spectral_preset((*object)["preset"])
                      : read_spectral_file((*object)["file"]);
  }

  std::optional<MaterialModel> read_spectral_preset(const json& value) {
    const std::string pointer = "/spectral/preset";
    std::vector<std::string_view> symbols;
    for (const MetalPreset& preset : metal_presets())
      symbols.push_back(preset.symbol);
    const std::string allowed = fmt::format("one of {}", join(symbols));
    if (!value.is_string()) {
      error(pointer, fmt::format("is {}", describe_type(value)), allowed);
      return std::nullopt;
    }
    const std::string symbol = value.get<std::string>();
    const MetalPreset* preset = find_metal_preset(symbol);
    if (!preset) {
      const auto suggestion = closest_match(symbol, symbols);
      error(pointer,
            suggestion ? fmt::format("unknown preset '{}' (did you mean '{}'?)", echoed(symbol),
                                     *suggestion)
                       : fmt::format("unknown preset '{}'", echoed(symbol)),
            allowed);
      return std::nullopt;
    }
    if (!preset->caveat.empty()) {
      diagnostics_.warning(at_value(pointer), field_path(pointer),
                           fmt::format("preset '{}' is unreliable: {}", symbol, preset->caveat),
                           "prefer an ior or artistic material for this metal");
    }
    SpectralInput input;
    input.preset = symbol;
    input.spectrum = preset_spectrum(*preset);
    return input;
  }

  std::optional<MaterialModel> read_spectral_file(const json& value) {
    const std::string pointer = "/spectral/file";
    const std::string allowed = "a path to a CSV of wavelength_nm,n,k, relative to this file";
    if (!value.is_string() || value.get<std::string>().empty()) {
      error(pointer, value.is_string() ? "is empty" : fmt::format("is {}", describe_type(value)),
            allowed);
      return std::nullopt;
    }
    SpectralInput input;
    input.file = value.get<std::string>();
    const std::filesystem::path resolved = base_directory_ / input.file;
    input.resolved_file = resolved.lexically_normal().generic_string();
    const LoadedFile loaded = loader_(resolved, kMaxSpectrumFileBytes);
    if (!loaded.bytes) {
      error(pointer,
            fmt::format("cannot read '{}': {}", echoed(input.resolved_file, 128), loaded.error),
            allowed);
      return std::nullopt;
    }
    const TextLocator csv_locator(input.resolved_file, *loaded.bytes);
    auto spectrum = parse_nk_csv(*loaded.bytes, csv_locator, diagnostics_);
    references_.push_back({input.resolved_file, at_value(pointer)});
    if (!spectrum) return std::nullopt;
    input.spectrum = std::move(*spectrum);
    input.file_bytes = *loaded.bytes;
    return input;
  }

 public:
  // Data files this material names, and where: problems inside one also point back here.
  struct Reference {
    std::string path;
    SourceLocation location;
  };
  const std::vector<Reference>& references() const { return references_; }

 private:
  const FileLoader& loader_;
  std::filesystem::path base_directory_;
  std::vector<Reference> references_;
};

}  // namespace

std::string material_name_key(std::string_view name) {
  std::string key(name);
  std::transform(key.begin(), key.end(), key.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return key;
}

std::optional<std::string> material_name_problem(std::string_view name) {
  if (name.empty()) return "is empty";
  if (name.size() > kMaxMaterialNameLength) {
    return fmt::format("is {} characters long", name.size());
  }
  const auto is_letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); };
  const auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    if (is_letter(c) || c == '_' || (i > 0 && is_digit(c))) continue;
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) {
      return fmt::format("contains a non-ASCII or control byte at position {}", i + 1);
    }
    return fmt::format("'{}' is not an identifier ('{}' at position {})", echoed(name), c, i + 1);
  }
  // Generated identifiers are "matc_<kind>_<name>"; GLSL reserves every name containing "__".
  if (name.front() == '_' || name.find("__") != std::string_view::npos) {
    return fmt::format(
        "'{}' would make generated names such as matc_fresnel_{} contain '__', "
        "which GLSL reserves",
        name, name);
  }
  if (const std::string_view identifier = identifier_taken_by_library(name); !identifier.empty()) {
    return fmt::format("'{}' would make {}, which the shared library defines", name, identifier);
  }
  return std::nullopt;
}

ParseResult parse_material(std::string_view text, const std::string& path,
                           const FileLoader& loader) {
  ParseResult result;
  const TextLocator locator(path, text);
  const auto document = parse_located_json_reporting(text, locator, result.diagnostics);
  if (!document) return result;
  const std::filesystem::path base_directory = std::filesystem::path(path).parent_path();
  MaterialReader reader(*document, locator, result.diagnostics, loader, base_directory);
  result.material = reader.read();
  if (result.material) result.material->source_text = std::string(text);
  // Report in reading order: the material file's problems by position, then its data files'.
  std::stable_sort(result.diagnostics.items().begin(), result.diagnostics.items().end(),
                   [&](const Diagnostic& a, const Diagnostic& b) {
                     const auto key = [&](const Diagnostic& d) {
                       return std::tuple(d.location.path != path, d.location.line,
                                         d.location.column);
                     };
                     return key(a) < key(b);
                   });
  // As compilers do for includes: a problem inside a data file names the material that read it.
  for (const auto& reference : reader.references())
    note_referenced_from(result.diagnostics, reference.path, reference.location, "spectral.file");
  return result;
}

ParseResult read_material_file(const std::string& path, const FileLoader& loader) {
  const LoadedFile loaded = loader(path, kMaxMaterialFileBytes);
  if (!loaded.bytes) {
    ParseResult result;
    result.diagnostics.error({path, 0, 0}, "", fmt::format("cannot read: {}", loaded.error),
                             "a material JSON file of at most 1 MiB");
    return result;
  }
  return parse_material(*loaded.bytes, path, loader);
}

}  // namespace matc
