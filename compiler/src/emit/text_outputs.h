// The outputs of a build that are text made from templates and numbers: the shader libraries
// (matc_fresnel.{glsl,hlsl,wgsl}), each material's snippets and JSON, and the hashes that name
// them. No shader is compiled and no table baked here, so that a build without glslang (the
// WebAssembly library) makes the same bytes as `matc`; Build adds the SPIR-V and the tables.
#pragma once

#include <cstddef>
#include <string>

#include "compile/compile.h"
#include "emit/build_options.h"
#include "lut/preintegrate.h"
#include "spirv/shader_language.h"

namespace matc {

class TextOutputs {
 public:
  // `coefficient_table_size`: the build's coefficient table's width (MATC_COEFFICIENT_TABLE_SIZE);
  // `embedded_luts`: --embed-lut's tables, one per layer, or none; they must outlive this.
  TextOutputs(const BuildOptions& options, std::size_t coefficient_table_size,
              std::span<const Lut> embedded_luts);

  // The hash of the options the shared files derive from.
  const std::string& inputs_hash() const { return inputs_hash_; }
  const std::string& library_source(ShaderLanguage language) const;
  // The GLSL library without the textured-metal and area-light functions, which no material
  // module calls: each <name>.spv compiles it, and glslang parsing the unused functions cost a
  // fifth of a batch.
  const std::string& material_module_library() const { return glsl_material_module_library_; }

  // The hash of what a material's outputs derive from: matc's version, these options, the
  // material's JSON and any spectral file it names, as parsed (nothing is read again: a material
  // parsed from memory works the same).
  std::string material_inputs_hash(const Material& material) const;
  std::string material_source(ShaderLanguage language, const CompiledMaterial& compiled) const;
  bool per_material_basis() const { return per_material_; }
  // <name>.json, with the material's inputs hash.
  std::string material_json(const CompiledMaterial& compiled, std::string_view inputs_hash) const;

 private:
  bool per_material_;        // --basis auto: a layer per basis (build_options.h)
  std::string options_key_;  // the options the shared files derive from
  std::string color_key_;    // the working space and gamut mapping: every material's numbers
  std::string inputs_hash_;
  std::string glsl_library_;
  std::string hlsl_library_;
  std::string wgsl_library_;
  std::string glsl_material_module_library_;
};

}  // namespace matc
