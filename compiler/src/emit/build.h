// Everything one `matc` run writes: the shared library, the tables, and per material its
// snippets, SPIR-V, C header and JSON. A facade over the modules that make them: the output
// layout names the files (output_layout.h), SharedTables makes the tables (shared_tables.h), the
// shader library and snippet generators and library_module.h the shaders, ManifestWriter the
// manifest (manifest_writer.h). The CLI decides where files go.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "compile/basis_choice.h"
#include "compile/compile.h"
#include "emit/build_options.h"
#include "emit/c_header.h"
#include "emit/output_layout.h"
#include "emit/shader_literals.h"
#include "emit/shared_tables.h"
#include "emit/text_outputs.h"
#include "fit/coefficient_table.h"
#include "lut/lut_files.h"
#include "spirv/shader_compiler.h"

namespace matc {

struct MaterialOutputs {
  std::string name;
  std::string source_path;
  std::string inputs_hash;
  std::vector<OutputFile> files;
};

class Build {
 public:
  // Bakes the table(s) and generates the shared library. Throws std::invalid_argument for options
  // out of range.
  explicit Build(BuildOptions options);

  const BuildOptions& options() const { return options_; }
  // The basis every material of a one-basis build is compiled against (options().basis), the
  // first layer's in a per-material build.
  runtime::BasisView basis() const;
  BasisChoice basis_choice() const;
  // The basis `material` is compiled against in this build (compile/basis_choice.h).
  runtime::BasisView basis_for(const Material& material) const;
  // The bases of the table's layers, in order (one unless --basis auto), and where `basis` is
  // among them (std::invalid_argument if the table holds none of it).
  const std::vector<runtime::BasisKind>& lut_layers() const { return tables_.layers(); }
  std::size_t lut_layer(runtime::BasisKind basis) const { return tables_.layer_of(basis); }
  // The table is baked on first use (the LUT file, a header or the manifest naming its hash,
  // validation): a run that writes none of those never pays for it.
  const BakedLut& lut() const { return tables_.lut(); }
  // The table as the written file stores it (f16 rounding), what a renderer samples.
  const Lut& stored_lut() const { return tables_.stored_lut(); }
  // `basis`' layer of it, and every layer side by side (the texture the file holds).
  const Lut& stored_lut(runtime::BasisKind basis) const { return tables_.stored_lut(basis); }
  const LutAtlas& stored_atlas() const { return tables_.stored_atlas(); }
  // --embed-lut's table of `basis`' layer; null without one.
  const Lut* embedded_lut(runtime::BasisKind basis) const { return tables_.embedded_lut(basis); }
  // The basis' coefficient table as the written file stores it (the preintegrated table's format,
  // coefficient_table_precision): what a shader samples for textured metals.
  const CoefficientTable& stored_coefficient_table() const {
    return tables_.stored_coefficient_table();
  }
  const std::string& inputs_hash() const { return texts_.inputs_hash(); }

  const std::string& library_source(ShaderLanguage language) const {
    return texts_.library_source(language);
  }
  std::string material_source(ShaderLanguage language, const CompiledMaterial& compiled) const {
    return texts_.material_source(language, compiled);
  }

  // The hash of what a material's outputs derive from: matc's version, these options, the
  // material's JSON and any spectral file it names, as parsed (nothing is read again: a material
  // parsed from memory works the same).
  std::string material_inputs_hash(const Material& material) const {
    return texts_.material_inputs_hash(material);
  }

  // The files matc_fresnel.{glsl,hlsl,spv}, matc_lut.<ext>, matc_coefficient_table.<ext> and
  // matc_ltc.<ext> (each with its .json) the options select.
  std::vector<OutputFile> shared_outputs() const;
  // <name>.{glsl,hlsl,spv,h,json} as selected.
  MaterialOutputs material_outputs(const CompiledMaterial& compiled) const;

  // What the shared library module (matc_fresnel.spv) is compiled from: its GLSL, its name and the
  // functions it exports (emit/library_module.h).
  struct LibraryModuleInputs {
    std::string glsl_source;
    std::string name;
    std::vector<std::string> exports;
  };
  LibraryModuleInputs shared_library_module_inputs() const;

  // The linkable library module of one material (exports matc_fresnel_<name> and
  // matc_fresnel_preintegrated_<name>), optimised and validated.
  SpirvWords material_library_module(const CompiledMaterial& compiled) const;
  // The same, always by a glslang compile (material_library_module patches a checked-in template
  // where one holds: emit/material_module_template.h).
  SpirvWords compile_material_library_module(const CompiledMaterial& compiled) const;
  // What the build is (version, inputs hash, --emit, basis, colour, the tables' files and hashes):
  // the head of matc_manifest.json (emit/manifest_writer.h).
  nlohmann::ordered_json description() const;

 private:
  SpirvWords material_library_module(const CompiledMaterial& compiled,
                                     std::string_view inputs_hash) const;
  SpirvWords compile_material_library_module(const CompiledMaterial& compiled,
                                             std::string_view inputs_hash) const;
  BuildOptions options_;
  SharedTables tables_;
  TextOutputs texts_;
};

}  // namespace matc
