#include "lut/analytic_lut_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Dense>

#include "fit/coefficients.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/shader_basis.h"
#include "matc/version.h"
#include "optics/presets.h"
#include "optics/spectral.h"

namespace matc {
namespace {

constexpr std::size_t kAlbedoDegree = runtime::kAnalyticLutAlbedoDegree;
constexpr std::size_t kQuadratureDegree = runtime::kAnalyticLutQuadratureDegree;
constexpr std::size_t kAlbedoTerms = runtime::analytic_lut_terms(kAlbedoDegree);
constexpr std::size_t kFieldTerms = runtime::analytic_lut_terms(kQuadratureDegree);
constexpr std::size_t kFields = 3;                          // mu_a, mu_b, t
constexpr std::size_t kChannels = runtime::kBasisSize - 1;  // bbar_1..bbar_3, fitted by the nodes
constexpr int kMaxIterations = 200;
constexpr double kConverged = 1e-9;

// T_p(x) T_q(y) for p + q <= degree, in analytic_lut_polynomial's order.
Eigen::RowVectorXd chebyshev_terms(const runtime::AnalyticLutChebyshev& tx,
                                   const runtime::AnalyticLutChebyshev& ty, std::size_t degree) {
  Eigen::RowVectorXd row(static_cast<Eigen::Index>(runtime::analytic_lut_terms(degree)));
  Eigen::Index term = 0;
  for (std::size_t p = 0; p <= degree; ++p)
    for (std::size_t q = 0; q + p <= degree; ++q)
      row(term++) = tx[p] * ty[q];
  return row;
}

// The shader basis and its derivative in mu (central differences; zero where the shaders clamp).
struct BasisSlope {
  std::array<double, runtime::kBasisSize> value{};
  std::array<double, runtime::kBasisSize> slope{};
};
BasisSlope basis_with_slope(const runtime::ShaderBasis& basis, double mu) {
  BasisSlope out;
  out.value = runtime::evaluate_shader_basis(basis, mu);
  if (mu <= 0.0 || mu >= 1.0) return out;
  constexpr double kStep = 1e-6;
  const double above = std::min(mu + kStep, 1.0), below = std::max(mu - kStep, 0.0);
  const auto high = runtime::evaluate_shader_basis(basis, above);
  const auto low = runtime::evaluate_shader_basis(basis, below);
  for (std::size_t i = 0; i < runtime::kBasisSize; ++i)
    out.slope[i] = (high[i] - low[i]) / (above - below);
  return out;
}

// The texel centres: their Chebyshev terms for E and for the quadrature, and their texels.
struct FitPoints {
  Eigen::MatrixXd albedo_terms;  // points x kAlbedoTerms
  Eigen::MatrixXd field_terms;   // points x kFieldTerms
  Eigen::MatrixXd texels;        // points x 4
};

FitPoints fit_points(const Lut& table) {
  const runtime::LutView view = table.view();
  const auto points = static_cast<Eigen::Index>(table.size * table.size);
  FitPoints out{Eigen::MatrixXd(points, kAlbedoTerms), Eigen::MatrixXd(points, kFieldTerms),
                Eigen::MatrixXd(points, runtime::kBasisSize)};
  Eigen::Index row = 0;
  for (std::size_t j = 0; j < table.size; ++j) {
    for (std::size_t i = 0; i < table.size; ++i, ++row) {
      const double last = static_cast<double>(table.size - 1);
      const double ndotv = runtime::lut_ndotv_from_u(static_cast<double>(i) / last);
      const double roughness = static_cast<double>(j) / last;
      const auto [x, y] = runtime::analytic_lut_coordinates(ndotv, roughness);
      const auto tx = runtime::analytic_lut_chebyshev(x);
      const auto ty = runtime::analytic_lut_chebyshev(y);
      out.albedo_terms.row(row) = chebyshev_terms(tx, ty, kAlbedoDegree);
      out.field_terms.row(row) = chebyshev_terms(tx, ty, kQuadratureDegree);
      const auto texel = view.texel(i, j);
      for (std::size_t c = 0; c < runtime::kBasisSize; ++c)
        out.texels(row, static_cast<Eigen::Index>(c)) = texel[c];
    }
  }
  return out;
}

// The root mean square of c_1..c_3 over the measured metals: how much an error in bbar_i moves
// their Fbar.
std::array<double, kChannels> channel_weights(runtime::BasisKind kind) {
  std::array<double, kChannels> weights{};
  const auto metals = measured_metal_coefficients(runtime::shipped_basis(kind));
  for (std::size_t i = 0; i < kChannels; ++i) {
    double sum = 0.0;
    for (const runtime::Coefficients& metal : metals)
      for (const auto& channel : metal)
        sum += channel[i + 1] * channel[i + 1];
    weights[i] = std::sqrt(sum / static_cast<double>(3 * metals.size()));
  }
  return weights;
}

// The quadrature's residuals (weighted model - texel, per point and channel 1..3) at `fields`
// (kFields x kFieldTerms coefficients, stacked), and the normal equations J^T J, J^T r. Each row
// of J is three scalars times the point's Chebyshev terms, so J^T J is built from six weighted
// Gram matrices of those terms rather than from J itself.
struct QuadratureModel {
  const FitPoints& points;
  const Eigen::VectorXd& albedo;  // E at each point
  const runtime::ShaderBasis& basis;
  std::array<double, kChannels> weights;
  bool clamp_weight = true;  // as the shaders do; off for the first stage of the fit

  double cost(const Eigen::VectorXd& fields, Eigen::MatrixXd* normal = nullptr,
              Eigen::VectorXd* gradient = nullptr) const {
    const Eigen::Index n = points.field_terms.rows();
    const auto terms = static_cast<Eigen::Index>(kFieldTerms);
    const Eigen::VectorXd node_a = points.field_terms * fields.segment(0, terms);
    const Eigen::VectorXd node_b = points.field_terms * fields.segment(terms, terms);
    const Eigen::VectorXd weight_b = points.field_terms * fields.segment(2 * terms, terms);
    // s[f](point, channel): d(residual)/d(field f) per unit of the point's terms.
    std::array<Eigen::MatrixXd, kFields> s;
    for (auto& m : s)
      m.resize(n, static_cast<Eigen::Index>(kChannels));
    Eigen::MatrixXd residual(n, static_cast<Eigen::Index>(kChannels));
    for (Eigen::Index k = 0; k < n; ++k) {
      const BasisSlope a = basis_with_slope(basis, node_a(k));
      const BasisSlope b = basis_with_slope(basis, node_b(k));
      // The shaders clamp the weight to [0, 1] (runtime/analytic_lut.h): so does the model.
      const double e = albedo(k);
      const double t = clamp_weight ? std::clamp(weight_b(k), 0.0, 1.0) : weight_b(k);
      const bool t_free = !clamp_weight || (weight_b(k) > 0.0 && weight_b(k) < 1.0);
      for (std::size_t c = 0; c < kChannels; ++c) {
        const auto col = static_cast<Eigen::Index>(c);
        const double w = weights[c];
        residual(k, col) =
            w * (e * ((1.0 - t) * a.value[c + 1] + t * b.value[c + 1]) - points.texels(k, col + 1));
        s[0](k, col) = w * e * (1.0 - t) * a.slope[c + 1];
        s[1](k, col) = w * e * t * b.slope[c + 1];
        s[2](k, col) = t_free ? w * e * (b.value[c + 1] - a.value[c + 1]) : 0.0;
      }
    }
    if (normal) {
      normal->resize(3 * terms, 3 * terms);
      gradient->resize(3 * terms);
      for (std::size_t f = 0; f < kFields; ++f) {
        const Eigen::VectorXd along = (s[f].array() * residual.array()).rowwise().sum();
        gradient->segment(static_cast<Eigen::Index>(f) * terms, terms) =
            points.field_terms.transpose() * along;
        for (std::size_t g = f; g < kFields; ++g) {
          const Eigen::VectorXd scale = (s[f].array() * s[g].array()).rowwise().sum();
          const Eigen::MatrixXd block =
              points.field_terms.transpose() * scale.asDiagonal() * points.field_terms;
          normal->block(static_cast<Eigen::Index>(f) * terms, static_cast<Eigen::Index>(g) * terms,
                        terms, terms) = block;
          normal->block(static_cast<Eigen::Index>(g) * terms, static_cast<Eigen::Index>(f) * terms,
                        terms, terms) = block.transpose();
        }
      }
    }
    return residual.squaredNorm();
  }
};

// A start away from the symmetric saddle mu_a = mu_b: the single node mu that best fits each point
// (a search over [0, 1]), fitted, then spread by 0.1 either way with equal weights.
Eigen::VectorXd starting_fields(const QuadratureModel& model) {
  const Eigen::Index n = model.points.field_terms.rows();
  Eigen::VectorXd single(n);
  constexpr int kSteps = 400;
  std::vector<std::array<double, runtime::kBasisSize>> candidates(kSteps + 1);
  for (int s = 0; s <= kSteps; ++s)
    candidates[static_cast<std::size_t>(s)] =
        runtime::evaluate_shader_basis(model.basis, static_cast<double>(s) / kSteps);
  for (Eigen::Index k = 0; k < n; ++k) {
    double best = std::numeric_limits<double>::infinity();
    for (int s = 0; s <= kSteps; ++s) {
      double cost = 0.0;
      for (std::size_t c = 0; c < kChannels; ++c) {
        const double d = model.albedo(k) * candidates[static_cast<std::size_t>(s)][c + 1] -
                         model.points.texels(k, static_cast<Eigen::Index>(c + 1));
        cost += model.weights[c] * model.weights[c] * d * d;
      }
      if (cost < best) {
        best = cost;
        single(k) = static_cast<double>(s) / kSteps;
      }
    }
  }
  const auto solver = model.points.field_terms.householderQr();
  const auto terms = static_cast<Eigen::Index>(kFieldTerms);
  Eigen::VectorXd fields(3 * terms);
  fields.segment(0, terms) = solver.solve((single.array() - 0.1).matrix());
  fields.segment(terms, terms) = solver.solve((single.array() + 0.1).matrix());
  fields.segment(2 * terms, terms) = solver.solve(Eigen::VectorXd::Constant(n, 0.5));
  return fields;
}

Eigen::VectorXd levenberg_marquardt(const QuadratureModel& model, Eigen::VectorXd fields) {
  Eigen::MatrixXd normal;
  Eigen::VectorXd gradient;
  double cost = model.cost(fields, &normal, &gradient);
  double damping = 1e-3;
  for (int iteration = 0; iteration < kMaxIterations && damping < 1e8; ++iteration) {
    Eigen::MatrixXd damped = normal;
    damped.diagonal() += damping * normal.diagonal().cwiseMax(1e-12);
    const Eigen::VectorXd candidate = fields - damped.ldlt().solve(gradient);
    const double candidate_cost = model.cost(candidate);
    if (candidate_cost < cost) {
      // Converged once a step gains less than a part in 1e9 (about 50 steps from the start).
      if (cost - candidate_cost < kConverged * cost) return candidate;
      fields = candidate;
      cost = model.cost(fields, &normal, &gradient);
      damping = std::max(damping * 0.3, 1e-9);
    } else {
      damping *= 10.0;
    }
  }
  return fields;
}

template <std::size_t N>
std::array<double, N> to_array(const Eigen::VectorXd& values, Eigen::Index offset) {
  std::array<double, N> out{};
  for (std::size_t i = 0; i < N; ++i)
    out[i] = values(offset + static_cast<Eigen::Index>(i));
  return out;
}

}  // namespace

runtime::AnalyticLutCoefficients fit_analytic_lut(const Lut& table, runtime::BasisKind kind) {
  const FitPoints points = fit_points(table);
  const Eigen::VectorXd albedo_coefficients =
      points.albedo_terms.householderQr().solve(points.texels.col(0));
  const Eigen::VectorXd albedo = points.albedo_terms * albedo_coefficients;
  // Unclamped first (smooth, so it finds the good basin), then as the shaders evaluate it.
  QuadratureModel model{points, albedo, runtime::shipped_shader_basis(kind), channel_weights(kind),
                        false};
  const Eigen::VectorXd unclamped = levenberg_marquardt(model, starting_fields(model));
  model.clamp_weight = true;
  const Eigen::VectorXd fields = levenberg_marquardt(model, unclamped);

  runtime::AnalyticLutCoefficients result;
  result.basis = kind;
  result.albedo = to_array<kAlbedoTerms>(albedo_coefficients, 0);
  const auto terms = static_cast<Eigen::Index>(kFieldTerms);
  result.node_a = to_array<kFieldTerms>(fields, 0);
  result.node_b = to_array<kFieldTerms>(fields, terms);
  result.weight_b = to_array<kFieldTerms>(fields, 2 * terms);
  return result;
}

runtime::AnalyticLutCoefficients fit_shipped_analytic_lut(runtime::BasisKind kind) {
  return fit_analytic_lut(preintegrate_lut(runtime::shipped_basis(kind), LutOptions{}), kind);
}

std::vector<runtime::Coefficients> measured_metal_coefficients(const runtime::BasisView& basis) {
  std::vector<runtime::Coefficients> metals;
  for (const MetalPreset& preset : metal_presets()) {
    if (preset.caveat.empty())
      metals.push_back(solve_coefficients(SpectralCurve(preset_spectrum(preset)), basis));
  }
  return metals;
}

AnalyticLutError analytic_lut_error(const runtime::AnalyticLutCoefficients& analytic,
                                    const Lut& texture, const runtime::BasisView& basis) {
  const std::vector<runtime::Coefficients> metals = measured_metal_coefficients(basis);
  constexpr std::size_t kGrid = 65;
  AnalyticLutError error;
  std::size_t count = 0;
  for (std::size_t j = 0; j < kGrid; ++j) {
    for (std::size_t i = 0; i < kGrid; ++i) {
      const double ndotv = static_cast<double>(i) / (kGrid - 1);
      const double roughness = static_cast<double>(j) / (kGrid - 1);
      const auto closed_form = runtime::preintegrated_basis_analytic(analytic, ndotv, roughness);
      const auto fetched = runtime::sample_lut(texture.view(), ndotv, roughness);
      for (const runtime::Coefficients& coefficients : metals) {
        const runtime::Rgb a = runtime::combine(coefficients, closed_form);
        const runtime::Rgb b = runtime::combine(coefficients, fetched);
        for (std::size_t c = 0; c < 3; ++c) {
          const double difference = std::abs(a[c] - b[c]);
          error.max = std::max(error.max, difference);
          if (ndotv >= 0.25)
            error.max_away_from_grazing = std::max(error.max_away_from_grazing, difference);
          error.mean += difference;
          ++count;
        }
      }
    }
  }
  error.mean /= static_cast<double>(count);
  return error;
}

std::string analytic_lut_source(runtime::BasisKind kind,
                                const runtime::AnalyticLutCoefficients& coefficients) {
  const std::string name(runtime::basis_name(kind));
  std::string out = fmt::format(
      "// Generated by `matc basis analytic-lut --basis {0}` (matc {1}). Do not edit: rerun it.\n"
      "// The closed form of the {0} basis' preintegrated table: the coefficients of\n"
      "// T_p(x) T_q(y) of E, mu_a, mu_b and t (matc/runtime/analytic_lut.h).\n"
      "// clang-format off\n"
      "#include \"matc/runtime/analytic_lut.h\"\n\n"
      "namespace matc::runtime {{\n\n"
      "const AnalyticLutCoefficients& {0}_analytic_lut() {{\n"
      "  static constexpr AnalyticLutCoefficients kCoefficients = {{\n"
      "    BasisKind::{0},\n",
      name, kVersion);
  const auto append = [&](const char* what, std::span<const double> values) {
    out += fmt::format("    // {}\n    {{", what);
    for (std::size_t i = 0; i < values.size(); ++i)
      out += fmt::format("{}{}", i == 0 ? "" : (i % 4 == 0 ? ",\n     " : ", "),
                         values[i]);  // shortest round trip
    out += "},\n";
  };
  append("E", coefficients.albedo);
  append("mu_a", coefficients.node_a);
  append("mu_b", coefficients.node_b);
  append("t", coefficients.weight_b);
  out +=
      "  };\n"
      "  return kCoefficients;\n"
      "}\n\n"
      "}  // namespace matc::runtime\n";
  return out;
}

}  // namespace matc
