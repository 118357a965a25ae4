#include "matc/api/gltf.h"

#include <map>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "base/echoed_text.h"
#include "checked_options.h"
#include "compile/f0_table.h"
#include "emit/gltf_fresnel_extension.h"
#include "input_files.h"
#include "matc/runtime/basis.h"
#include "material/document_import.h"
#include "material/gltf_import.h"
#include "public_diagnostics.h"

namespace matc::api {
namespace {

// Schlick's curve at F0 = 0: F82-tint with a white tint, as the importer writes a glTF metal.
constexpr std::string_view kZeroF0Schlick =
    R"({"name": "zero_f0", "color_space": "lin_rec709",
        "f82_tint": {"f0": [0, 0, 0], "tint": [1, 1, 1]}})";

void require_gltf_path(std::string_view path) {
  if (!is_gltf_path(path))
    throw std::invalid_argument(fmt::format(
        "path: '{}' names no glTF asset; a path ending in .gltf or .glb", echoed(path)));
}

GltfAsset compile_imported(std::string_view bytes, const std::string& path,
                           const CompileOptions& options, const FileLoader& loader) {
  basis_choice_of(options);   // an option outside its names throws before any work
  color_options_of(options);  // likewise
  DocumentImport imported = import_document(bytes, path, loader);
  throw_if_errors(imported.diagnostics);
  const std::vector<Diagnostic> notes = public_diagnostics(imported.diagnostics);
  GltfAsset asset;
  asset.notes = notes;
  std::map<std::size_t, nlohmann::ordered_json> extensions;
  // The coefficients at F0 = 0 of Schlick's curve, for the textured metals (the same for each),
  // in each basis a metal is compiled against (one, unless --basis auto).
  std::map<runtime::BasisKind, CompiledMaterial> zero_f0;
  for (ImportedMaterial& material : imported.materials) {
    const std::size_t index = material.document_index;
    const bool per_pixel_f0 = material.per_pixel_f0;
    Material value(std::make_shared<const matc::Material>(std::move(material.material)), notes);
    asset.materials.push_back(compile(value, options));
    const matc::CompiledMaterial& compiled = asset.materials.back().value();
    const runtime::BasisView basis = runtime::shipped_basis(compiled.basis);
    if (per_pixel_f0 && !zero_f0.contains(compiled.basis)) {
      CompileOptions in_basis = options;
      in_basis.basis = std::string(runtime::basis_name(compiled.basis));
      zero_f0.emplace(compiled.basis,
                      compile(parse_materials(kZeroF0Schlick, "zero_f0.json").front(), in_basis));
    }
    // A working space or a gamut mapping that mixes the channels leaves the table out: each
    // entry compiles the three channels at one F0.
    std::optional<runtime::F0Table> f0_table;
    if (material.f0_table && has_f0_table(compiled.material, compiled.color))
      f0_table = compile_f0_table(compiled.material, basis, compiled.color);
    extensions.emplace(
        index, gltf_fresnel_extension(compiled, basis,
                                      per_pixel_f0 ? &zero_f0.at(compiled.basis).value() : nullptr,
                                      f0_table ? &*f0_table : nullptr));
  }
  Diagnostics diagnostics;
  std::optional<GltfWithExtensions> written = gltf_with_fresnel_extensions(
      bytes, path_has_extension(path, ".glb"), extensions, path, diagnostics);
  throw_if_errors(diagnostics);
  asset.bytes = std::move(written->bytes);
  asset.external_uris = std::move(written->external_uris);
  return asset;
}

}  // namespace

GltfAsset compile_gltf(std::string_view bytes, std::string_view path,
                       const CompileOptions& options) {
  require_gltf_path(path);
  return compile_imported(bytes, std::string(path), options, load_file);
}

GltfAsset compile_gltf(std::string_view bytes, std::string_view path, const CompileOptions& options,
                       const InputFiles& files) {
  require_gltf_path(path);
  check_input_files(files);
  const std::string input(path);
  return compile_imported(bytes, input, options, memory_file_loader(files, input));
}

GltfAsset compile_gltf_file(std::string_view path, const CompileOptions& options) {
  require_gltf_path(path);
  const std::string file(path);
  Diagnostics diagnostics;
  const std::optional<std::string> bytes = read_document_bytes(file, diagnostics);
  throw_if_errors(diagnostics);
  return compile_imported(*bytes, file, options, load_file);
}

}  // namespace matc::api
