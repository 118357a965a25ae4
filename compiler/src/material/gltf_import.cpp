#include "material/gltf_import.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "base/echoed_text.h"
#include "base/shared_file_stems.h"
#include "gltf_asset.h"
#include "material/basis_pin.h"
#include "material/materialx_import.h"

namespace matc {

namespace {

// The keys of the files every build writes once (matc_lut, matc_fresnel, ...): a material of
// such a name would write over them, so a glTF material named so takes a derived name.
const std::set<std::string>& shared_stem_keys() {
  static const std::set<std::string> keys = [] {
    std::set<std::string> out;
    for (const std::string_view stem : kSharedFileStems)
      out.insert(material_name_key(stem));
    return out;
  }();
  return keys;
}

using nlohmann::ordered_json;

constexpr std::string_view kClearcoat = "KHR_materials_clearcoat";
constexpr std::string_view kClearcoatIor = "KHR_materials_clearcoat_ior";
constexpr std::string_view kSpecular = "KHR_materials_specular";
constexpr std::string_view kEdgeColor = "EXT_materials_specular_edge_color";
constexpr std::string_view kIridescence = "KHR_materials_iridescence";

// Material extensions that change a metal's reflectance in ways matc does not carry (named in
// a note when present), and those that make the material something other than a metal.
constexpr std::array<std::string_view, 7> kNotCarriedExtensions{
    "KHR_materials_anisotropy",
    "KHR_materials_sheen",
    "KHR_materials_transmission",
    "KHR_materials_volume",
    "KHR_materials_diffuse_transmission",
    "KHR_materials_dispersion",
    "KHR_materials_coat"};
constexpr std::array<std::string_view, 2> kNotMetalExtensions{"KHR_materials_pbrSpecularGlossiness",
                                                              "KHR_materials_unlit"};

const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, std::string_view name) {
  const auto found = extensions.find(std::string(name));
  return found == extensions.end() ? nullptr : &found->second;
}

bool has_texture(const tinygltf::Value& object, const char* key) {
  return object.IsObject() && object.Has(key) && object.Get(key).IsObject();
}

class Importer {
 public:
  Importer(const tinygltf::Model& model, const std::string& path, DocumentImport& result)
      : model_(model), path_(path), result_(result) {}

  void run() {
    // glTF's names need not be unique: a clash takes a derived name, never one a later material
    // holds itself.
    for (std::size_t i = 0; i < model_.materials.size(); ++i)
      names_held_.insert(material_name_key(sanitized_material_name(document_name(i))));
    for (std::size_t i = 0; i < model_.materials.size(); ++i)
      material(i);
    // An asset without a metal is valid, and a pipeline sees every asset: nothing to compile.
    if (result_.materials.empty() && !result_.diagnostics.has_errors()) {
      result_.diagnostics.note(
          {path_, 0, 0}, "",
          model_.materials.empty()
              ? std::string("holds no materials: nothing for matc to compile")
              : fmt::format("holds no metal (none of its {} materials has metallicFactor above "
                            "0): nothing for matc to compile",
                            model_.materials.size()));
    }
    if (result_.diagnostics.has_errors()) result_.materials.clear();
  }

 private:
  // The material's name, or `material_<index>` when it has none.
  std::string document_name(std::size_t index) const {
    const std::string& name = model_.materials[index].name;
    return name.empty() ? fmt::format("material_{}", index) : name;
  }

  // `materials[3] "CarPaint"` (the name escaped when printed), or `materials[3]`.
  std::string field_of(std::size_t index) const {
    const std::string& name = model_.materials[index].name;
    return name.empty() ? fmt::format("materials[{}]", index)
                        : fmt::format("materials[{}] \"{}\"", index, echoed(name, 64));
  }

  SourceLocation where() const { return {path_, 0, 0}; }

  void note(const std::string& field, const std::string& message) {
    result_.diagnostics.note(where(), field, message);
  }

  void error(const std::string& field, const std::string& message, const std::string& allowed) {
    result_.diagnostics.error(where(), field, message, allowed);
  }

  // A factor in [low, high], or an error naming the property.
  bool in_range(const std::string& field, const std::string& property, double value, double low,
                double high) {
    if (value >= low && value <= high) return true;
    error(field, fmt::format("{} is {}", property, value), fmt::format("[{}, {}]", low, high));
    return false;
  }

  // A number in an extension's object (its default where absent); false after an error.
  bool number(const std::string& field, const tinygltf::Value& object, const char* key,
              double& value) {
    if (!object.IsObject() || !object.Has(key)) return true;
    const tinygltf::Value& given = object.Get(key);
    if (!given.IsNumber()) {
      error(field, fmt::format("{} is not a number", key), "a number");
      return false;
    }
    value = given.GetNumberAsDouble();
    return true;
  }

  // An RGB array in an extension's object (its default where absent); false after an error.
  bool rgb(const std::string& field, const tinygltf::Value& object, const char* key, Rgb& value) {
    if (!object.IsObject() || !object.Has(key)) return true;
    const tinygltf::Value& given = object.Get(key);
    if (!given.IsArray() || given.ArrayLen() != 3 || !given.Get(0).IsNumber() ||
        !given.Get(1).IsNumber() || !given.Get(2).IsNumber()) {
      error(field, fmt::format("{} is not three numbers", key), "[r, g, b]");
      return false;
    }
    for (int c = 0; c < 3; ++c)
      value[static_cast<std::size_t>(c)] = given.Get(c).GetNumberAsDouble();
    return true;
  }

  void material(std::size_t index) {
    const tinygltf::Material& source = model_.materials[index];
    const std::string field = field_of(index);
    const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
    for (const std::string_view name : kNotMetalExtensions) {
      if (extension(source.extensions, name)) {
        note(field, fmt::format("not imported: {} is not a metallic-roughness metal", name));
        return;
      }
    }
    if (!(pbr.metallicFactor > 0)) {
      note(field, "not imported: not a metal (metallicFactor 0); the engine keeps it");
      return;
    }
    if (!in_range(field, "pbrMetallicRoughness.metallicFactor", pbr.metallicFactor, 0, 1)) return;
    if (pbr.baseColorFactor.size() != 4) {
      error(field, "pbrMetallicRoughness.baseColorFactor is not four numbers", "[r, g, b, a]");
      return;
    }
    Rgb f0{};
    for (std::size_t c = 0; c < 3; ++c) {
      f0[c] = pbr.baseColorFactor[c];
      if (!in_range(field, fmt::format("pbrMetallicRoughness.baseColorFactor[{}]", c), f0[c], 0, 1))
        return;
    }
    if (!in_range(field, "pbrMetallicRoughness.roughnessFactor", pbr.roughnessFactor, 0, 1)) return;
    std::vector<std::string> not_carried;
    ordered_json material_json;
    material_json["name"] = "";
    material_json["description"] = fmt::format("glTF materials[{}] of {}", index,
                                               std::filesystem::path(path_).filename().string());
    material_json["color_space"] = "lin_rec709";  // glTF's colours are linear Rec.709
    Rgb tint{1, 1, 1};                            // Schlick's curve: F82-tint with a white tint
    if (!edge_color(field, source, tint, not_carried)) return;
    const auto array = [](const Rgb& v) { return ordered_json::array({v[0], v[1], v[2]}); };
    material_json["f82_tint"] = {{"f0", array(f0)}, {"tint", array(tint)}};
    material_json["roughness"] = pbr.roughnessFactor;
    std::optional<ordered_json> coat;
    if (!read_coat(field, source, coat, not_carried)) return;
    metalness_notes(pbr, coat.has_value(), not_carried);
    std::optional<ordered_json> film;
    if (!read_film(field, source, film, not_carried)) return;
    // The film lies under the clear coat, seen from the coat's medium (docs/thin-film.md). The
    // extension's film of index 1 shows nothing (its formula takes the outside index for 1): under
    // a coat matc would see an air gap in it, so it is left out.
    if (film && !(coat && (*film)["ior"].get<double>() == 1.0))
      material_json["film"] = std::move(*film);
    // A textured Schlick metal is carried per pixel (its coefficients are linear in F0); an edge
    // colour, a coat or a film makes the curve's shape depend on F0 otherwise.
    const bool textured = pbr.baseColorTexture.index >= 0;
    const bool per_pixel_f0 =
        textured && tint == Rgb{1, 1, 1} && !coat && !material_json.contains("film");
    if (per_pixel_f0) {
      not_carried.push_back(
          "baseColorTexture (compiled at baseColorFactor; `matc gltf` writes the coefficients at "
          "F0 = 0 with which the npm package's loaders follow the texture per pixel)");
    } else if (textured) {
      not_carried.push_back(fmt::format(
          "baseColorTexture (compiled at baseColorFactor; under {} the curve is not linear in F0: "
          "`matc gltf` writes the coefficients at 33 values of F0, between which the npm "
          "package's loaders and native shaders interpolate a pixel's)",
          coat                             ? "a clear coat"
          : material_json.contains("film") ? "a thin film"
                                           : "an edge colour"));
    }
    if (coat) material_json["coat"] = std::move(*coat);
    const std::string_view layered = coat ? "coat" : material_json.contains("film") ? "film" : "";
    if (!basis_pin(field, source, layered, material_json)) return;
    for (const std::string_view name : kNotCarriedExtensions)
      if (extension(source.extensions, name)) not_carried.push_back(std::string(name));
    if (!not_carried.empty()) {
      std::string list;
      for (const std::string& entry : not_carried)
        list += (list.empty() ? "" : "; ") + entry;
      note(field, fmt::format("not carried: {} (matc compiles the metal's Fresnel; docs/gltf.md "
                              "lists what is left out and why)",
                              list));
    }
    const std::string name =
        names_.claim_unique(document_name(index), names_held_, shared_stem_keys(), where(), field,
                            field, result_.diagnostics);
    if (name.empty()) return;
    material_json["name"] = name;
    const std::size_t added = result_.materials.size();
    add_imported_material(result_, material_json, path_, where(), field);
    if (result_.materials.size() > added) {
      result_.materials.back().document_index = index;
      result_.materials.back().per_pixel_f0 = per_pixel_f0;
      result_.materials.back().f0_table = textured && !per_pixel_f0;
    }
  }

  // The material's basis pin, extras.matc_basis (material/basis_pin.h), into `material_json`;
  // false after an error.
  bool basis_pin(const std::string& field, const tinygltf::Material& source,
                 std::string_view layered, ordered_json& material_json) {
    const std::string key(kBasisPinAttribute);
    if (!source.extras.IsObject() || !source.extras.Has(key)) return true;
    const tinygltf::Value& given = source.extras.Get(key);
    if (!given.IsString()) {
      error(field, fmt::format("extras.{} is not a string", key), basis_pin_rule());
      return false;
    }
    const BasisPin pin = read_basis_pin(given.Get<std::string>(), layered);
    if (pin.problem) {
      error(field, fmt::format("extras.{}: {}", key, pin.problem->problem), pin.problem->allowed);
      return false;
    }
    material_json["basis"] = runtime::basis_name(*pin.basis);
    return true;
  }

  // Partial or textured metalness: the compile carries the metal, and glTF's mix with the
  // engine's dielectric is the shader's (matc_metal_rough; under a coat matc_metal_rough_<name>,
  // the dielectric seen through the coat).
  static void metalness_notes(const tinygltf::PbrMetallicRoughness& pbr, bool coated,
                              std::vector<std::string>& not_carried) {
    const std::string how = coated ? "the metal is compiled; the shader mixes it with the engine's "
                                     "dielectric under the coat, matc_metal_rough_<name>"
                                   : "the metal is compiled; the shader mixes it with the engine's "
                                     "dielectric, matc_metal_rough";
    if (pbr.metallicFactor < 1)
      not_carried.push_back(
          fmt::format("partial metalness (metallicFactor {}: {})", pbr.metallicFactor, how));
    if (pbr.metallicRoughnessTexture.index >= 0)
      not_carried.push_back(
          fmt::format("metallicRoughnessTexture's metalness ({}, per pixel)", how));
  }

  // EXT_materials_specular_edge_color inside KHR_materials_specular: the specular colour times
  // the specular factor is the metal's F82 tint (clamped to [0, 1], as the extension clamps).
  bool edge_color(const std::string& field, const tinygltf::Material& source, Rgb& tint,
                  std::vector<std::string>& not_carried) {
    const tinygltf::Value* specular = extension(source.extensions, kSpecular);
    if (!specular || !specular->IsObject()) return true;
    const tinygltf::Value& nested = specular->Get("extensions");
    const tinygltf::Value& edge = nested.IsObject() ? nested.Get(std::string(kEdgeColor)) : nested;
    const bool enabled = edge.IsObject() && edge.Has("specularEdgeColorEnabled") &&
                         edge.Get("specularEdgeColorEnabled").IsBool() &&
                         edge.Get("specularEdgeColorEnabled").Get<bool>();
    if (!enabled) return true;  // KHR_materials_specular alone does not change a metal
    double factor = 1;
    Rgb color{1, 1, 1};
    const std::string where_field = fmt::format("{}: {}", field, kSpecular);
    if (!number(where_field, *specular, "specularFactor", factor) ||
        !rgb(where_field, *specular, "specularColorFactor", color))
      return false;
    if (!in_range(field, std::string(kSpecular) + ".specularFactor", factor, 0, 1)) return false;
    bool clamped = false;
    for (std::size_t c = 0; c < 3; ++c) {
      if (!(color[c] >= 0)) {
        error(field, fmt::format("{}.specularColorFactor[{}] is {}", kSpecular, c, color[c]),
              "a number of at least 0");
        return false;
      }
      const double value = color[c] * factor;
      tint[c] = std::min(value, 1.0);
      clamped = clamped || value > 1;
    }
    if (clamped)
      note(field, fmt::format("{}'s edge colour above 1 clamped to 1 (as {} clamps it)", kSpecular,
                              kEdgeColor));
    if (has_texture(*specular, "specularTexture") || has_texture(*specular, "specularColorTexture"))
      not_carried.push_back(std::string(kSpecular) +
                            "'s textures (the edge colour is its factors)");
    return true;
  }

  // KHR_materials_iridescence: a film of coverage iridescenceFactor, index iridescenceIor (1.3)
  // and thickness iridescenceThicknessMaximum (400 nm), what the extension's film is without its
  // thickness texture. The textures are noted (a material file's thickness range compiles a
  // thickness per pixel; the importer does not write one yet). No film when the factor is 0.
  bool read_film(const std::string& field, const tinygltf::Material& source,
                 std::optional<ordered_json>& film, std::vector<std::string>& not_carried) {
    const tinygltf::Value* iridescence = extension(source.extensions, kIridescence);
    if (!iridescence || !iridescence->IsObject()) return true;
    const std::string where_field = fmt::format("{}: {}", field, kIridescence);
    double factor = 0, ior = 1.3, minimum = 100, maximum = 400;
    if (!number(where_field, *iridescence, "iridescenceFactor", factor) ||
        !number(where_field, *iridescence, "iridescenceIor", ior) ||
        !number(where_field, *iridescence, "iridescenceThicknessMinimum", minimum) ||
        !number(where_field, *iridescence, "iridescenceThicknessMaximum", maximum))
      return false;
    const std::string name(kIridescence);
    const auto thickness_in_range = [&](const char* key, double nm) {
      if (nm >= 0 && nm <= kMaxFilmThicknessNm) return true;
      error(field, fmt::format("{}.{} is {}", name, key, nm),
            fmt::format("a thickness in [0, {}] nanometres (the films matc compiles)",
                        kMaxFilmThicknessNm));
      return false;
    };
    if (!in_range(field, name + ".iridescenceFactor", factor, 0, 1) ||
        !thickness_in_range("iridescenceThicknessMinimum", minimum) ||
        !thickness_in_range("iridescenceThicknessMaximum", maximum))
      return false;
    if (!(ior >= 1)) {
      error(field, fmt::format("{}.iridescenceIor is {}", name, ior), "a film index of at least 1");
      return false;
    }
    if (factor == 0) return true;  // no film
    if (ior > kMaxFilmIor) {
      note(field, fmt::format("{}.iridescenceIor {} clamped to {} (the film indices matc compiles)",
                              name, ior, kMaxFilmIor));
      ior = kMaxFilmIor;
    }
    if (has_texture(*iridescence, "iridescenceTexture"))
      not_carried.push_back(name + "'s iridescenceTexture (the film's coverage is its factor)");
    if (has_texture(*iridescence, "iridescenceThicknessTexture"))
      not_carried.push_back(fmt::format(
          "{}'s iridescenceThicknessTexture (compiled at iridescenceThicknessMaximum, {} nm; a "
          "material file's thickness range compiles a thickness per pixel, which the importer "
          "does not write yet: docs/thin-film.md)",
          name, maximum));
    film = ordered_json{{"weight", factor}, {"ior", ior}, {"thickness", maximum}};
    return true;
  }

  // KHR_materials_clearcoat (and KHR_materials_clearcoat_ior inside it): a coat of weight
  // clearcoatFactor, roughness clearcoatRoughnessFactor and index clearcoatIor (1.5).
  bool read_coat(const std::string& field, const tinygltf::Material& source,
                 std::optional<ordered_json>& coat, std::vector<std::string>& not_carried) {
    const tinygltf::Value* clearcoat = extension(source.extensions, kClearcoat);
    if (!clearcoat || !clearcoat->IsObject()) return true;
    const std::string where_field = fmt::format("{}: {}", field, kClearcoat);
    double weight = 0, roughness = 0, ior = 1.5;
    if (!number(where_field, *clearcoat, "clearcoatFactor", weight) ||
        !number(where_field, *clearcoat, "clearcoatRoughnessFactor", roughness))
      return false;
    const tinygltf::Value& nested = clearcoat->Get("extensions");
    if (nested.IsObject() && nested.Has(std::string(kClearcoatIor)) &&
        !number(where_field, nested.Get(std::string(kClearcoatIor)), "clearcoatIor", ior))
      return false;
    if (!in_range(field, std::string(kClearcoat) + ".clearcoatFactor", weight, 0, 1) ||
        !in_range(field, std::string(kClearcoat) + ".clearcoatRoughnessFactor", roughness, 0, 1))
      return false;
    if (has_texture(*clearcoat, "clearcoatTexture") ||
        has_texture(*clearcoat, "clearcoatRoughnessTexture"))
      not_carried.push_back(std::string(kClearcoat) +
                            "'s weight and roughness textures (the coat "
                            "is its factors)");
    if (weight == 0) return true;  // no coat
    if (!(ior >= 1.05 && ior <= 3)) {
      error(field, fmt::format("{}.clearcoatIor is {}", kClearcoatIor, ior),
            "a coat index in [1.05, 3] (matc's coats; nearer 1 the coat's Fresnel is a spike no "
            "basis holds)");
      return false;
    }
    coat = ordered_json{{"weight", weight}, {"ior", ior}, {"roughness", roughness}};
    return true;
  }

  const tinygltf::Model& model_;
  const std::string& path_;
  DocumentImport& result_;
  DocumentNames names_;
  std::set<std::string> names_held_;  // every material's own name (its key)
};

}  // namespace

DocumentImport import_gltf(std::string_view bytes, const std::string& path,
                           const FileLoader& loader) {
  DocumentImport result;
  const std::optional<tinygltf::Model> model =
      read_gltf_asset(bytes, path, loader, result.diagnostics);
  if (!model) return result;
  Importer(*model, path, result).run();
  return result;
}

}  // namespace matc
