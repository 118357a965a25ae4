// matc.CompiledMaterial: a material's coefficients with what they were fitted to, evaluated over
// numpy arrays exactly as the CPU runtime (and so the shaders) computes them.
#pragma once

#include <memory>

#include "matc/compile/compile.h"
#include "matc/optics/reflectance_curve.h"
#include "matc/runtime/basis.h"
#include "materials.h"

namespace matc::python {

struct CompiledResult {
  CompiledMaterial compiled;
  runtime::BasisKind basis = runtime::kDefaultBasis;
  LoadedMaterialPointer material;
  // What the coefficients were fitted to; for a coated material the exact layered curve, which
  // refers to the two curves beside it.
  std::shared_ptr<const ReflectanceCurve> exact;
  std::shared_ptr<const ReflectanceCurve> in_air, under_coat;  // coated materials only
  Diagnostics diagnostics;  // the input's warnings and notes, then the fit's (as the CLI's)
};

using CompiledPointer = std::shared_ptr<CompiledResult>;

// compile_material with the GIL released, and the CLI's fit warnings and range notes.
CompiledPointer compile_loaded(const LoadedMaterialPointer& material, runtime::BasisKind basis,
                               const ColorOptions& color);

// The same for `compiled`, already compiled from `material` with `basis` and `color` (the exact
// curves it was fitted to are made here, with the GIL released).
CompiledPointer compiled_result(const LoadedMaterialPointer& material, CompiledMaterial compiled,
                                runtime::BasisKind basis, const ColorOptions& color);

}  // namespace matc::python
