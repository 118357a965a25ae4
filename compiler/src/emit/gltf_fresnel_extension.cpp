#include "emit/gltf_fresnel_extension.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "emit/material_json.h"
#include "formats/glb_container.h"
#include "matc/version.h"
#include "material/gltf_base64.h"
#include "material/located_json.h"

namespace matc {
namespace {

using nlohmann::ordered_json;

// One change to the JSON text: `erase` bytes at `offset` replaced by `insert`.
struct Edit {
  std::size_t offset = 0;
  std::size_t erase = 0;
  std::string insert;
};

// Errors located in the asset's JSON: at its line and column in a .gltf; in a GLB, at the file
// with the line and column of its JSON chunk in the message.
class JsonErrors {
 public:
  JsonErrors(std::string_view json, bool binary, const std::string& path, Diagnostics& diagnostics)
      : locator_(path, json), binary_(binary), diagnostics_(diagnostics) {}

  void error(std::size_t offset, const std::string& field, const std::string& message,
             const std::string& allowed) {
    const SourceLocation at = locator_.at(offset);
    if (!binary_) {
      diagnostics_.error(at, field, message, allowed);
      return;
    }
    diagnostics_.error(
        locator_.whole_file(), field,
        fmt::format("{} (line {}, column {} of its JSON chunk)", message, at.line, at.column),
        allowed);
  }
  bool has_errors() const { return diagnostics_.has_errors(); }

 private:
  TextLocator locator_;
  bool binary_;
  Diagnostics& diagnostics_;
};

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Edits the asset's JSON text; each problem is an error naming its entry.
class JsonSplicer {
 public:
  JsonSplicer(std::string_view text, const LocatedJson& document, JsonErrors& errors)
      : text_(text), document_(document), errors_(errors) {}

  std::optional<std::string> run(const std::map<std::size_t, ordered_json>& extensions) {
    if (!document_.value.is_object()) {
      errors_.error(0, "", "the asset's JSON is not an object", "a glTF 2.0 asset");
      return std::nullopt;
    }
    static const nlohmann::json kNoMaterials = nlohmann::json::array();
    const auto found_materials = document_.value.find("materials");
    const nlohmann::json& materials =
        found_materials == document_.value.end() ? kNoMaterials : *found_materials;
    if (!materials.is_array()) {
      error("/materials", "is not an array", "an array of materials");
      return std::nullopt;
    }
    for (std::size_t i = 0; i < materials.size(); ++i) {
      const auto found = extensions.find(i);
      material(i, materials[i], found == extensions.end() ? nullptr : &found->second);
    }
    if (!extensions.empty()) list_in_extensions_used();
    if (errors_.has_errors()) return std::nullopt;
    std::sort(edits_.begin(), edits_.end(),
              [](const Edit& a, const Edit& b) { return a.offset > b.offset; });
    std::string out(text_);
    for (const Edit& edit : edits_)
      out.replace(edit.offset, edit.erase, edit.insert);
    return out;
  }

 private:
  // An error at the value at `pointer`.
  void error(const std::string& pointer, const std::string& message, const std::string& allowed) {
    errors_.error(document_.value_offset(pointer), field_path(pointer), message, allowed);
  }

  // Inserts `text` (a member `"key":value` or an element) first in the object or array
  // `container` at `pointer`.
  void insert_first(const std::string& pointer, const nlohmann::json& container,
                    const std::string& text) {
    edits_.push_back(
        {document_.value_offset(pointer) + 1, 0, text + (container.empty() ? "" : ",")});
  }

  void material(std::size_t index, const nlohmann::json& value, const ordered_json* extension) {
    const std::string pointer = fmt::format("/materials/{}", index);
    if (!value.is_object()) {
      error(pointer, "is not an object", "a material object");
      return;
    }
    const std::string dumped =
        extension ? extension->dump(-1, ' ', false, ordered_json::error_handler_t::replace)
                  : std::string();
    const std::string member = fmt::format("\"{}\":{}", kGltfFresnelExtension, dumped);
    const auto extensions = value.find("extensions");
    if (extensions == value.end()) {
      if (extension) insert_first(pointer, value, fmt::format("\"extensions\":{{{}}}", member));
      return;
    }
    const std::string extensions_pointer = pointer + "/extensions";
    if (!extensions->is_object()) {
      error(extensions_pointer, "is not an object", "an object of extensions");
      return;
    }
    const std::string ours = fmt::format("{}/{}", extensions_pointer, kGltfFresnelExtension);
    const auto previous = extensions->find(std::string(kGltfFresnelExtension));
    if (previous == extensions->end()) {
      if (extension) insert_first(extensions_pointer, *extensions, member);
      return;
    }
    if (!previous->is_object()) {
      error(ours, "is not an object", "the object matc writes (docs/gltf.md)");
      return;
    }
    const std::size_t start = document_.value_offset(ours);
    const std::size_t end = document_.container_ends.at(ours);
    if (extension) {  // written by an earlier run: replaced
      edits_.push_back({start, end - start, dumped});
      return;
    }
    // The material is no longer a metal matc compiles: the member goes, with one comma.
    std::size_t from = document_.key_offsets.at(ours);
    std::size_t to = end;
    std::size_t after = to;
    while (after < text_.size() && is_space(text_[after]))
      ++after;
    if (after < text_.size() && text_[after] == ',') {
      to = after + 1;
    } else {
      std::size_t before = from;
      while (before > 0 && is_space(text_[before - 1]))
        --before;
      if (before > 0 && text_[before - 1] == ',') from = before - 1;
    }
    edits_.push_back({from, to - from, {}});
  }

  void list_in_extensions_used() {
    const std::string name = fmt::format("\"{}\"", kGltfFresnelExtension);
    const auto used = document_.value.find("extensionsUsed");
    if (used == document_.value.end()) {
      insert_first("", document_.value, fmt::format("\"extensionsUsed\":[{}]", name));
      return;
    }
    if (!used->is_array()) {
      error("/extensionsUsed", "is not an array", "an array of extension names");
      return;
    }
    if (std::find(used->begin(), used->end(), std::string(kGltfFresnelExtension)) != used->end())
      return;
    insert_first("/extensionsUsed", *used, name);
  }

  std::string_view text_;
  const LocatedJson& document_;
  JsonErrors& errors_;
  std::vector<Edit> edits_;
};

// The URIs of the asset's external files: buffers' and images' that are not data URIs.
std::vector<std::string> external_uris(const nlohmann::json& root) {
  std::vector<std::string> uris;
  for (const char* array : {"buffers", "images"}) {
    const auto entries = root.find(array);
    if (entries == root.end() || !entries->is_array()) continue;
    for (const nlohmann::json& entry : *entries) {
      const auto uri = entry.is_object() ? entry.find("uri") : entry.end();
      if (uri != entry.end() && uri->is_string() && !uri->get<std::string>().starts_with("data:"))
        uris.push_back(uri->get<std::string>());
    }
  }
  return uris;
}

// A filmed metal's table as the extension carries it: its RGB texels row after row (row 0 F, rows
// 1-17 Fbar, as <name>.film.<ext> lays them out), little-endian float32 (what a renderer samples),
// in base64: 18,720 characters, where the rows as JSON numbers took about 69 KB a metal (a glTF
// of Khronos's 343 filmed spheres grew from 133 KB to 24 MB).
ordered_json film_table_extension_json(const runtime::FilmTable& table) {
  const std::vector<float> rgba = runtime::film_table_texels(table);
  std::string bytes;
  bytes.reserve(rgba.size() / 4 * 3 * sizeof(float));
  for (std::size_t i = 0; i < rgba.size(); ++i) {
    if (i % 4 == 3) continue;  // alpha: 1 everywhere
    std::uint32_t bits = 0;    // std::memcpy: emscripten's libc++ has no std::bit_cast
    std::memcpy(&bits, &rgba[i], sizeof bits);
    for (int shift = 0; shift < 32; shift += 8)
      bytes.push_back(static_cast<char>((bits >> shift) & 0xFFu));
  }
  return {{"width", runtime::FilmTable::kWidth},
          {"height", runtime::FilmTable::kHeight},
          {"texels", gltf_base64(bytes)}};
}

}  // namespace

ordered_json gltf_fresnel_extension(const CompiledMaterial& compiled,
                                    const runtime::BasisView& basis,
                                    const CompiledMaterial* zero_f0,
                                    const runtime::F0Table* f0_table) {
  ordered_json out;
  out["name"] = compiled.material.name;
  out["basis"] = runtime::basis_name(basis.kind);
  out["matcVersion"] = kVersion;
  out["colorSpace"] = color_space_name(compiled.color.working_space);
  out["coefficients"] = coefficient_rows_json(compiled.coefficients);
  if (zero_f0) out["zeroF0Coefficients"] = coefficient_rows_json(zero_f0->coefficients);
  if (f0_table) {
    const auto entries = [](const std::array<runtime::Coefficients, runtime::kF0TableEntries>& at) {
      ordered_json rows = ordered_json::array();
      for (const runtime::Coefficients& coefficients : at)
        rows.push_back(coefficient_rows_json(coefficients));
      return rows;
    };
    ordered_json table;
    table["coefficients"] = entries(f0_table->in_air);
    if (f0_table->under_coat) table["underCoatCoefficients"] = entries(*f0_table->under_coat);
    out["f0Table"] = std::move(table);
  }
  out["maxError"] = rgb_json(compiled.accuracy.decomposition.max_abs);
  if (compiled.coat) {
    const CompiledCoat& coat = *compiled.coat;
    const runtime::CoatCoefficients& c = coat.coefficients;
    out["maxError"] = rgb_json(coat.layered_error.max_abs);
    out["coat"] = {{"weight", coat.input.weight},
                   {"ior", coat.input.ior},
                   {"roughness", coat.input.roughness},
                   {"color", rgb_json(coat.input.color)},
                   {"underCoatCoefficients", coefficient_rows_json(c.under_coat)},
                   {"coatCoefficients", {c.coat[0], c.coat[1], c.coat[2], c.coat[3]}}};
  }
  if (compiled.film_table) {
    // A filmed metal (docs/thin-film.md): its shaders read F and Fbar from its own table, carried
    // here so that an engine needs no other file; `coefficients` give F0. Under a coat the table
    // is the base lobe, and maxError stays both lobes' against the exact layered curve.
    const FilmInput& film = *compiled.material.film;
    if (!compiled.coat) out["maxError"] = rgb_json(compiled.film_table_error.max_abs);
    out["film"] = {{"weight", film.weight},
                   {"ior", film.ior},
                   {"thickness", film.thickness_nm},
                   {"table", film_table_extension_json(*compiled.film_table)}};
  }
  return out;
}

std::optional<GltfWithExtensions> gltf_with_fresnel_extensions(
    std::string_view asset, bool binary, const std::map<std::size_t, ordered_json>& extensions,
    const std::string& path, Diagnostics& diagnostics) {
  GlbParts parts{asset, {}};
  if (binary) {
    if (const std::string problem = glb_layout_problem(asset); !problem.empty()) {
      diagnostics.error({path, 0, 0}, "", problem, "a GLB 2.0 container");
      return std::nullopt;
    }
    parts = glb_parts(asset);
  }
  JsonErrors errors(parts.json, binary, path, diagnostics);
  auto parsed = parse_located_json(parts.json);
  if (const auto* syntax = std::get_if<JsonSyntaxError>(&parsed)) {
    errors.error(syntax->offset, "", syntax->message, "a glTF 2.0 asset");
    return std::nullopt;
  }
  const LocatedJson& document = std::get<LocatedJson>(parsed);
  // A key given twice is read as its last value by tinygltf; an edit could land in either.
  const TextLocator locator(path, parts.json);
  for (const DuplicateKey& duplicate : document.duplicates) {
    const SourceLocation first = locator.at(duplicate.first_offset);
    errors.error(duplicate.offset, field_path(duplicate.pointer),
                 fmt::format("given twice (first at line {}, column {})", first.line, first.column),
                 "each key once (readers differ on which one counts)");
  }
  if (diagnostics.has_errors()) return std::nullopt;
  std::optional<std::string> json = JsonSplicer(parts.json, document, errors).run(extensions);
  if (!json) return std::nullopt;
  GltfWithExtensions result;
  result.bytes = binary ? glb_file(*json, parts.after_json) : std::move(*json);
  result.external_uris = external_uris(document.value);
  return result;
}

}  // namespace matc
