#include "basis/basis_fit.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <Eigen/Dense>
#include <Eigen/SVD>

#include "basis/basis_polynomial_fit.h"
#include "basis/training_set.h"
#include "matc/runtime/shader_basis.h"
#include "matc/runtime/shipped_bases.h"
#include "matc/version.h"
#include "optics/fresnel.h"
#include "optics/gulbrandsen.h"

namespace matc {
namespace {

using Eigen::Index;

// The training curves, one per row, normalised to run from 1 (mu = 0) to 0 (mu = 1).
Eigen::MatrixXd normalized_curves(std::span<const TrainingCurve> training, std::size_t samples,
                                  Eigen::VectorXd& f0) {
  const auto rows = static_cast<Index>(training.size());
  const auto columns = static_cast<Index>(samples);
  Eigen::MatrixXd curves(rows, columns);
  f0.resize(rows);
  for (Index row = 0; row < rows; ++row) {
    const TrainingCurve& curve = training[static_cast<std::size_t>(row)];
    f0(row) = curve(1.0);
    for (Index j = 0; j < columns; ++j) {
      const double mu = static_cast<double>(j) / static_cast<double>(columns - 1);
      curves(row, j) = (curve(mu) - f0(row)) / (1.0 - f0(row));
    }
  }
  return curves;
}

Eigen::VectorXd curve_weights(const Eigen::VectorXd& f0, CurveWeighting weighting) {
  if (weighting == CurveWeighting::one_minus_f0) return (1.0 - f0.array()).matrix();
  return Eigen::VectorXd::Ones(f0.size());
}

// Square roots of the per-cosine weights, so that the SVD minimises the weighted squared error.
// mu = 0 keeps the weight of its neighbour: every curve is exactly 1 there.
Eigen::VectorXd cosine_weight_roots(std::size_t samples, CosineWeighting weighting) {
  const auto columns = static_cast<Index>(samples);
  Eigen::VectorXd roots = Eigen::VectorXd::Ones(columns);
  if (weighting == CosineWeighting::projected_solid_angle) {
    for (Index j = 0; j < columns; ++j)
      roots(j) =
          std::sqrt(static_cast<double>(std::max<Index>(j, 1)) / static_cast<double>(columns - 1));
  }
  return roots;
}

// Scales v so that its largest-magnitude entry becomes +1 (fixes the SVD's arbitrary sign).
std::vector<double> scaled_to_unit_peak(const Eigen::VectorXd& v) {
  Index peak = 0;
  v.cwiseAbs().maxCoeff(&peak);
  const Eigen::VectorXd scaled = v / v(peak);
  return {scaled.data(), scaled.data() + scaled.size()};
}

std::size_t index_of_max(const std::vector<double>& values) {
  return static_cast<std::size_t>(std::max_element(values.begin(), values.end()) - values.begin());
}
std::size_t index_of_min(const std::vector<double>& values) {
  return static_cast<std::size_t>(std::min_element(values.begin(), values.end()) - values.begin());
}
std::size_t distance(std::size_t a, std::size_t b) {
  return a > b ? a - b : b - a;
}

// mu_1 = argmax b_2, mu_2 = the extremum of b_3 farther from mu_1.
std::array<std::size_t, 2> probes_of(const FittedBasis& basis) {
  const std::size_t probe1 = index_of_max(basis.tables[1]);
  const std::size_t b3_max = index_of_max(basis.tables[2]);
  const std::size_t b3_min = index_of_min(basis.tables[2]);
  return {probe1, distance(b3_max, probe1) > distance(b3_min, probe1) ? b3_max : b3_min};
}

}  // namespace

runtime::BasisView FittedBasis::view() const {
  return {{tables[0], tables[1], tables[2]}, probe_indices, kind};
}

FittedBasis fit_basis(std::span<const ComplexIor> training, const BasisConstruction& construction) {
  std::vector<TrainingCurve> curves;
  curves.reserve(training.size());
  for (const ComplexIor ior : training)
    curves.emplace_back([ior](double mu) { return fresnel_exact(mu, ior); });
  return fit_basis(curves, construction);
}

FittedBasis fit_basis(std::span<const TrainingCurve> training,
                      const BasisConstruction& construction) {
  Eigen::VectorXd f0;
  const Eigen::MatrixXd curves = normalized_curves(training, construction.samples, f0);
  const Eigen::VectorXd rows = curve_weights(f0, construction.curve_weighting);
  const Eigen::VectorXd columns =
      cosine_weight_roots(construction.samples, construction.cosine_weighting);

  FittedBasis basis;
  Eigen::VectorXd b1;
  if (construction.mean_shape == MeanShape::mean_curve) {
    const Eigen::VectorXd squared = rows.cwiseAbs2();
    b1 = (curves.transpose() * squared) / squared.sum();
  } else {
    const Eigen::MatrixXd weighted = rows.asDiagonal() * curves * columns.asDiagonal();
    const Eigen::BDCSVD<Eigen::MatrixXd> first(weighted, Eigen::ComputeThinV);
    b1 = first.matrixV().col(0).cwiseQuotient(columns).cwiseAbs();
    b1 /= b1.maxCoeff();
  }
  basis.tables[0].assign(b1.data(), b1.data() + b1.size());

  const Eigen::MatrixXd residual =
      rows.asDiagonal() * (curves.rowwise() - b1.transpose()) * columns.asDiagonal();
  const Eigen::BDCSVD<Eigen::MatrixXd> second(residual, Eigen::ComputeThinV);
  basis.tables[1] = scaled_to_unit_peak(second.matrixV().col(0).cwiseQuotient(columns));
  basis.tables[2] = scaled_to_unit_peak(second.matrixV().col(1).cwiseQuotient(columns));

  basis.probe_indices = probes_of(basis);
  basis.shader = fit_basis_polynomial(basis.view());
  return basis;
}

std::vector<ComplexIor> paper_training_iors(const PaperBasisOptions& options) {
  std::vector<ComplexIor> iors =
      dielectric_training_iors(options.dielectric_curves, options.eta_min, options.eta_max);
  // The notebook's conductors: Gulbrandsen with edge tint g = 1, r over (0, 1).
  for (const ComplexIor ior : artistic_training_iors({options.conductor_curves, 1, 1.0, 1.0}))
    iors.push_back(ior);
  return iors;
}

FittedBasis fit_paper_basis(const PaperBasisOptions& options) {
  FittedBasis basis = fit_basis(paper_training_iors(options), {.samples = options.samples});
  basis.kind = runtime::BasisKind::paper;
  return basis;
}

std::vector<ComplexIor> extended_training_iors() {
  std::vector<ComplexIor> iors =
      paper_training_iors({.conductor_curves = kExtendedTrainingEdgeTintCurves});
  for (const ComplexIor ior : complex_ior_training_iors(kExtendedTrainingGrid))
    iors.push_back(ior);
  return iors;
}

FittedBasis fit_extended_basis() {
  FittedBasis basis = fit_basis(extended_training_iors(), kExtendedConstruction);
  basis.kind = runtime::BasisKind::extended;
  return basis;
}

FittedBasis closed_form_fitted_basis(runtime::BasisKind kind) {
  assert(runtime::is_closed_form(kind));
  const runtime::BasisView view = runtime::shipped_basis(kind);
  FittedBasis basis;
  for (std::size_t i = 0; i < basis.tables.size(); ++i)
    basis.tables[i].assign(view.tables[i].begin(), view.tables[i].end());
  basis.probe_indices = view.probe_indices;
  basis.shader = runtime::shipped_shader_basis(kind);
  basis.kind = kind;
  return basis;
}

namespace {

// The basis table's header comment: what each construction was trained on.
std::string paper_training() {
  const PaperBasisOptions options;
  return fmt::format(
      "// Training set: {} dielectrics (eta in [{}, {}]) and {} Gulbrandsen conductors "
      "(g = 1).\n// Unweighted SVDs (the authors).\n",
      options.dielectric_curves, options.eta_min, options.eta_max, options.conductor_curves);
}

std::string extended_training() {
  const PaperBasisOptions options;
  const ComplexIorGrid& grid = kExtendedTrainingGrid;
  return fmt::format(
      "// Training set: {} dielectrics (eta in [{}, {}]), {} Gulbrandsen conductors (g = "
      "1) and {} x {}\n// conductors (n in [{}, {}] log-spaced, k in [{}, {}]).\n"
      "// SVDs with every curve weighted by 1 - F0.\n",
      options.dielectric_curves, options.eta_min, options.eta_max, kExtendedTrainingEdgeTintCurves,
      grid.n_steps, grid.k_steps, grid.n_min, grid.n_max, grid.k_min, grid.k_max);
}

std::string closed_form_training() {
  return "// b_1..b_3: the closed form of runtime/powers_basis.h (nothing fitted).\n";
}

// How each shipped basis (runtime/shipped_bases.h) is made: its fit and what its table's header
// says about it.
struct ShippedBasisRecipe {
  runtime::BasisKind kind;
  FittedBasis (*fit)();
  std::string (*training)();
};

constexpr std::array<ShippedBasisRecipe, runtime::kShippedBases.size()> kRecipes = {{
    {runtime::BasisKind::powers,
     [] { return closed_form_fitted_basis(runtime::BasisKind::powers); }, closed_form_training},
    {runtime::BasisKind::extended, fit_extended_basis, extended_training},
    {runtime::BasisKind::paper, [] { return fit_paper_basis(); }, paper_training},
    {runtime::BasisKind::f82, [] { return closed_form_fitted_basis(runtime::BasisKind::f82); },
     closed_form_training},
}};

const ShippedBasisRecipe& recipe(runtime::BasisKind kind) {
  return *std::find_if(kRecipes.begin(), kRecipes.end(),
                       [kind](const ShippedBasisRecipe& entry) { return entry.kind == kind; });
}

}  // namespace

FittedBasis fit_shipped_basis(runtime::BasisKind kind) {
  return recipe(kind).fit();
}

std::string basis_table_source(const FittedBasis& basis) {
  const std::string name(runtime::basis_name(basis.kind));
  const std::string training = recipe(basis.kind).training();
  std::string out = fmt::format(
      "// Generated by `matc basis fit --basis {}` (matc {}). Do not edit: rerun it instead.\n"
      "{}"
      "// {} samples of mu = cos(theta) in [0, 1].\n"
      "// clang-format off\n"
      "#include \"matc/runtime/basis.h\"\n"
      "#include \"matc/runtime/basis_polynomial.h\"\n\n"
      "namespace matc::runtime {{\n"
      "namespace {{\n\n",
      name, kVersion, training, basis.tables[0].size());
  for (std::size_t i = 0; i < basis.tables.size(); ++i) {
    out += fmt::format("constexpr double kB{}[{}] = {{\n", i + 1, basis.tables[i].size());
    for (std::size_t j = 0; j < basis.tables[i].size(); ++j) {
      // fmt's shortest round-trip formatting reproduces every double exactly.
      out += fmt::format("{}{},", j % 4 == 0 ? "  " : " ", basis.tables[i][j]);
      if (j % 4 == 3 || j + 1 == basis.tables[i].size()) out += "\n";
    }
    out += "};\n\n";
  }
  out += fmt::format(
      "// The shaders' form: per segment, (b_1, b_2, b_3) coefficients of t^{} .. t^0.\n"
      "constexpr BasisPolynomial kPolynomial = {{{{\n",
      runtime::kPolynomialDegree);
  for (const runtime::PolynomialSegment& segment : basis.shader.polynomial) {
    out += "  {{\n";
    for (const auto& triple : segment)
      out += fmt::format("    {{{}, {}, {}}},\n", triple[0], triple[1], triple[2]);
    out += "  }},\n";
  }
  out += fmt::format(
      "}}}};\n\n"
      "}}  // namespace\n\n"
      "BasisView {0}_basis() {{ return {{{{kB1, kB2, kB3}}, {{{1}, {2}}}, BasisKind::{0}}}; }}\n\n"
      "const BasisPolynomial& {0}_basis_polynomial() {{ return kPolynomial; }}\n\n"
      "}}  // namespace matc::runtime\n",
      name, basis.probe_indices[0], basis.probe_indices[1]);
  return out;
}

}  // namespace matc
