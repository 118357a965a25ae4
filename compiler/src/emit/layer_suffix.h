// The suffix a further layer of a per-material build's table (--basis auto) appends to the
// library's function names: matc_fresnel_f82, matc_lut_texcoord_f82 (templates/*/basis_layer.*).
#pragma once

#include <string>

#include "matc/runtime/basis.h"

namespace matc {

inline std::string layer_suffix(runtime::BasisKind basis) {
  std::string suffix = "_";
  suffix += runtime::basis_name(basis);
  return suffix;
}

}  // namespace matc
