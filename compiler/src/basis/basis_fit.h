// Fitting the Fresnel basis b_1..b_3 from a training set of exact curves (Belcour et al. 2020).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "basis/training_set.h"
#include "optics/fresnel.h"

#include "matc/runtime/basis.h"
#include "matc/runtime/shader_basis.h"

namespace matc {

// The authors' training set: curves of mu sampled at `samples` points mu_j = j / (samples - 1),
// 99% dielectrics with eta evenly spread over [eta_min, eta_max] and 1% Gulbrandsen conductors with
// edge tint g = 1 and reflectivity evenly spread over (0, 1). Strata midpoints stand in for the
// notebook's uniform random draws, so the fit is deterministic.
struct PaperBasisOptions {
  std::size_t samples = 1000;
  std::size_t dielectric_curves = 990;
  std::size_t conductor_curves = 10;
  double eta_min = 1.01;
  double eta_max = 3.0;
};

// An owning basis table, as produced by a fit.
struct FittedBasis {
  std::array<std::vector<double>, runtime::kBasisSize - 1> tables;  // b_1, b_2, b_3
  std::array<std::size_t, 2> probe_indices{};
  // How the shaders evaluate it: the piecewise polynomial fitted to the tables
  // (fit_basis_polynomial), or the powers basis' closed form.
  runtime::ShaderBasis shader{};
  runtime::BasisKind kind = runtime::BasisKind::paper;  // which coefficient solve it is meant for

  runtime::BasisView view() const;
};

// How b_1 is taken from the normalised curves (F - F0) / (1 - F0).
enum class MeanShape {
  first_singular_vector,  // the authors: |first right singular vector| scaled to max 1
  mean_curve,             // the (weighted) mean curve: makes b_2, b_3 principal components
};
// How much each training curve counts in the SVDs.
enum class CurveWeighting {
  equal,         // every normalised curve alike (the authors)
  one_minus_f0,  // by 1 - F0: the scale the normalisation divided out, so the SVD minimises
                 // the error in F itself rather than in the normalised curve
};
// How much each cosine counts.
enum class CosineWeighting {
  solid_angle,            // uniform in mu: every direction of the hemisphere alike
  projected_solid_angle,  // by mu, as the cosine-weighted split sum weighs them
};

struct BasisConstruction {
  std::size_t samples = 1000;
  MeanShape mean_shape = MeanShape::first_singular_vector;
  CurveWeighting curve_weighting = CurveWeighting::equal;
  CosineWeighting cosine_weighting = CosineWeighting::solid_angle;
};

// b_1 per `construction.mean_shape`; b_2, b_3 = first two right singular vectors of the
// (weighted) residual normalised curve - b_1, each scaled so that its largest-magnitude entry is
// +1. Probes: mu_1 = argmax b_2, mu_2 = the extremum of b_3 farther from mu_1. The polynomial form
// is fitted to the resulting tables.
FittedBasis fit_basis(std::span<const ComplexIor> training, const BasisConstruction& construction);
// The same over any grey curves F(mu) with F(0) = 1 and F(1) < 1 (studies that train on other
// models' curves, such as F82-tint's).
using TrainingCurve = std::function<double(double)>;
FittedBasis fit_basis(std::span<const TrainingCurve> training,
                      const BasisConstruction& construction);

// The authors' training set and construction.
std::vector<ComplexIor> paper_training_iors(const PaperBasisOptions& options = {});
FittedBasis fit_paper_basis(const PaperBasisOptions& options = {});

// The default basis' training set: the authors' 990 dielectrics, extended with conductors that
// cover real metals (the (n, k) grid kExtendedTrainingGrid) and kExtendedTrainingEdgeTintCurves
// Gulbrandsen conductors with g = 1 (the most strongly tinted edges); each curve weighted by
// 1 - F0, uniform in mu. bench/accuracy/basis_study.cpp compares it with the other candidates.
inline constexpr ComplexIorGrid kExtendedTrainingGrid = {40, 40, 0.05, 4.0, 1.0, 8.0};
inline constexpr std::size_t kExtendedTrainingEdgeTintCurves = 100;
inline constexpr BasisConstruction kExtendedConstruction = {1000, MeanShape::first_singular_vector,
                                                            CurveWeighting::one_minus_f0,
                                                            CosineWeighting::solid_angle};
std::vector<ComplexIor> extended_training_iors();
FittedBasis fit_extended_basis();

// A closed-form basis (runtime::is_closed_form: powers, f82) as a FittedBasis: its closed form
// tabulated, its shader form the closed form itself. Nothing is fitted.
FittedBasis closed_form_fitted_basis(runtime::BasisKind kind);

// Refits a shipped basis from scratch (what `matc basis fit --basis NAME` does); a closed form is
// returned as closed_form_fitted_basis(kind).
FittedBasis fit_shipped_basis(runtime::BasisKind kind);

// The C++ source of runtime/src/generated/<name>_basis_table.cpp for a refit shipped basis.
std::string basis_table_source(const FittedBasis& basis);

}  // namespace matc
