// What a public CompiledMaterial's evaluations need beside the compiled value, shared by the files
// that implement them (compiled_material.cpp; fbar_reference.cpp, native builds), and the public
// value of a material the library compiled itself (a batch's, for its check).
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "compile/basis_choice.h"
#include "compile/compile.h"
#include "matc/api/compiled_material.h"
#include "matc/runtime/basis.h"
#include "optics/reflectance_curve.h"

namespace matc::api {

// The basis, and the exact curves the coefficients were fitted to (the material in air and, for
// a coated one, the metal under its coat and both layered, which refers to the other two), made
// on first use: a compile whose curves nobody evaluates does not pay for them.
struct CompiledMaterial::Evaluation {
  runtime::BasisKind basis = runtime::kDefaultBasis;
  bool per_material_build = true;  // compiled as a default build does: its basis its own
  ColorOptions color;
  std::shared_ptr<const matc::Material> material;

  struct Curves {
    std::unique_ptr<ReflectanceCurve> in_air;
    std::unique_ptr<ReflectanceCurve> under_coat;  // coated materials only
    std::unique_ptr<ReflectanceCurve> layered;     // coated materials only
  };
  const Curves& curves() const;
  const ReflectanceCurve& exact() const {
    const Curves& made = curves();
    return made.layered ? *made.layered : *made.in_air;
  }

 private:
  mutable std::once_flag made_;
  mutable Curves curves_;
};

// The public value of `compiled`, compiled by the library in a build of `choice` (its basis the
// one compiled.basis names) and its colour options; its diagnostics are `diagnostics`.
CompiledMaterial public_compiled(std::shared_ptr<const matc::CompiledMaterial> compiled,
                                 const BasisChoice& choice, std::vector<Diagnostic> diagnostics);

}  // namespace matc::api
