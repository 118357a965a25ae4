// What a public CompiledMaterial's evaluations need beside the compiled value, shared by the files
// that implement them (compiled_material.cpp; fbar_reference.cpp, native builds).
#pragma once

#include <memory>

#include "matc/api/compiled_material.h"
#include "matc/optics/reflectance_curve.h"
#include "matc/runtime/basis.h"

namespace matc::api {

// What the evaluations need beside the compiled value: the basis, and the exact curves the
// coefficients were fitted to (the material in air and, for a coated one, the metal under its
// coat and both layered, which refers to the other two).
struct CompiledMaterial::Evaluation {
  runtime::BasisKind basis = runtime::kDefaultBasis;
  std::unique_ptr<ReflectanceCurve> in_air;
  std::unique_ptr<ReflectanceCurve> under_coat;
  std::unique_ptr<ReflectanceCurve> layered;
  const ReflectanceCurve& exact() const { return layered ? *layered : *in_air; }
};

}  // namespace matc::api
