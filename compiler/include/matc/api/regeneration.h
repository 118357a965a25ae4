// The C++ sources of the tables matc ships (runtime/src/generated/, compiler/src/generated/), made
// again from their definitions: what `matc basis fit` and its siblings write. For maintainers
// (docs/maintainers.md): a change to a fit or a training set is checked in by rerunning these.
// Native builds.
#pragma once

#include <cstddef>
#include <string>

namespace matc::api {

enum class CheckedInSource {
  basis_table,        // <basis>_basis_table.cpp: b_1..b_3 refitted from the training set
  coefficient_table,  // <basis>_coefficient_table.cpp: c_2, c_3 over reflectivity and edge tint
  analytic_lut,       // <basis>_analytic_lut_table.cpp: the closed form of the default table
  lut_hashes,         // default_lut_hashes.cpp: every basis' default table files' hashes
  material_modules,   // material_module_templates.cpp: the SPIR-V each material is patched from
  library_modules,    // library_module_cache.cpp: the default build's matc_fresnel.spv
  ltc_table,          // ltc_table.cpp: GGX's LTC inverse matrices
};

struct RegenerationOptions {
  // The per-basis sources' basis, by --basis's names (empty: the default). basis_table takes the
  // fitted bases only (runtime::kFittedBases); a closed form throws std::invalid_argument.
  std::string basis;
  // ltc_table: what the fit minimises, by option_names("ltc_objective") (empty: "polygons", the
  // shipped one), its threads (0: one per core), and, when not 0, the reference samples per
  // quad light with which each texel's quality is measured into quality_csv.
  std::string ltc_objective;
  unsigned threads = 0;
  std::size_t quality_samples = 0;
};

struct RegeneratedSource {
  std::string source;       // the C++ file, byte for byte what is checked in when nothing changed
  std::string summary;      // one line on what was made ("fitted basis: probes mu_1 = ...")
  std::string quality_csv;  // ltc_table with quality_samples: x, y, ndotv, roughness, errors
};

RegeneratedSource regenerate_source(CheckedInSource source,
                                    const RegenerationOptions& options = {});

}  // namespace matc::api
