// Reading materials: a material file's JSON, a MaterialX document or a glTF asset, from a file or
// from text (docs/material-format.md, docs/interchange.md). Every reader validates the whole input
// and throws MaterialError with all its errors located; warnings and notes stay with the material.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "matc/api/diagnostics.h"

namespace matc {
struct Material;
}

namespace matc::api {

using Rgb = std::array<double, 3>;

// A material model's values by the material file's field names: RGB triples ("reflectivity" and
// "edge_tint"; "n" and "k"; "f0" and "tint") and, for a spectral material, "preset" or "file".
struct ModelInputs {
  std::vector<std::pair<std::string, Rgb>> colors;
  std::vector<std::pair<std::string, std::string>> texts;
};

// One validated material. Cheap to copy (shared, immutable).
class Material {
 public:
  const std::string& name() const;
  // "artistic", "ior", "spectral" or "f82_tint".
  std::string model() const;
  // The file it was read from, or the name given with its text.
  const std::string& path() const;
  // Its material file's JSON (for a MaterialX material, what `matc import` writes).
  const std::string& json() const;
  bool coated() const;
  ModelInputs inputs() const;
  // Its perceptual roughness and the colour space its RGB values are written in, where it says.
  std::optional<double> roughness() const;
  std::optional<std::string> color_space() const;
  // The input's warnings and notes.
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

  // The library's own value, for the library's implementation.
  const matc::Material& value() const { return *value_; }
  Material(std::shared_ptr<const matc::Material> value, std::vector<Diagnostic> diagnostics);

 private:
  std::shared_ptr<const matc::Material> value_;
  std::vector<Diagnostic> diagnostics_;
};

// The materials of `text`, an input called `path` in diagnostics: a MaterialX document when
// `path` ends in .mtlx, a glTF asset (its metals) when it ends in .gltf or .glb (any number of
// materials), else a material file's JSON (one). Relative spectral files and a glTF's external
// buffers resolve against `path`'s folder.
std::vector<Material> parse_materials(std::string_view text, std::string_view path);
// Files an input names (a spectral CSV, a .gltf's buffers), held in memory: each by its path
// relative to the input's folder as the input names it ("spectra/gold.csv", "car.bin").
using InputFiles = std::map<std::string, std::string>;
// The same with the files the input names given in memory: they are the only files read (a name
// not among them cannot be read). A name that could not be a file beside the input (absolute,
// climbing out, empty) throws std::invalid_argument naming it.
std::vector<Material> parse_materials(std::string_view text, std::string_view path,
                                      const InputFiles& files);
// One material from a material file's JSON, whatever `path` ends in.
Material parse_material_json(std::string_view json, std::string_view path);
// The same for a file.
std::vector<Material> load_materials(std::string_view path);

// Whether this library reads MaterialX documents: every build does (the native library with
// pugixml, the WebAssembly one with rapidxml, docs/interchange.md); kept for callers that ask.
bool reads_materialx();

// The names a spectral material's "preset" takes: the measured metals matc ships.
std::vector<std::string> spectral_presets();

}  // namespace matc::api
