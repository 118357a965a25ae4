// CompiledMaterial::fbar_reference: native builds only (the Monte-Carlo references are).
#include <optional>

#include "checked_values.h"
#include "compile/compile.h"
#include "compiled_evaluation.h"
#include "lut/layered_reference.h"
#include "lut/split_sum_reference.h"
#include "matc/api/compiled_material.h"

namespace matc::api {

static_assert(CompiledMaterial::kReferenceSamples == matc::kReferenceSamples);

std::vector<double> CompiledMaterial::fbar_reference(std::span<const double> ndotv,
                                                     std::span<const double> roughness,
                                                     std::size_t samples) const {
  check_ndotv_roughness(ndotv, roughness);
  checked_count("samples", samples, 16, std::size_t{1} << 26);
  if (ndotv.empty()) return {};
  // Tabulated once per call: a spectral curve is costly to evaluate at every sample.
  const Evaluation::Curves& curves = evaluation_->curves();
  const TabulatedCurve in_air(*curves.in_air);
  std::optional<TabulatedCurve> under_coat;
  if (curves.under_coat) under_coat.emplace(*curves.under_coat);
  std::vector<double> rgb(3 * ndotv.size());
  for (std::size_t i = 0; i < ndotv.size(); ++i) {
    // A coated material: the split-sum layering with exact curves, as matc eval's
    // Fbar_reference.
    const Rgb value =
        value_->coat
            ? layered_split_sum(in_air, *under_coat, value_->coat->input, ndotv[i], roughness[i])
            : SplitSumEstimator(ndotv[i], roughness[i], samples).integrate(in_air);
    for (std::size_t c = 0; c < 3; ++c)
      rgb[3 * i + c] = value[c];
  }
  return rgb;
}

}  // namespace matc::api
