// The coefficient-table study of issue #14 (docs/accuracy.md, "The coefficient table"): how the
// table that gives textured metals their coefficients at run time should be laid out (axes,
// size, what a texel stores, which solve fills it, precision), against a closed form with no
// fetch, and what the chosen table costs in accuracy on every test set of the basis study.
//   matc_table_study [--designs-only]   (bench/accuracy/update-docs.sh runs it in full)
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <future>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <Eigen/Dense>

#include "compile/compile.h"
#include "fit/accuracy.h"
#include "fit/coefficient_table.h"
#include "fit/coefficients.h"
#include "gulbrandsen_look.h"
#include "lut/coefficient_table_files.h"
#include "lut/preintegrate.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/lut.h"
#include "matc/runtime/shader_basis.h"
#include "optics/gulbrandsen.h"
#include "random_artistic.h"
#include "test_sets.h"

namespace {

using matc::ArtisticParameters;
using matc::CoefficientTable;
using matc::CoefficientTableOptions;
using matc::runtime::ChannelCoefficients;
using namespace matc::bench;

constexpr auto kBasis = matc::runtime::kDefaultBasis;
constexpr double kMaxReflectivity = 0.95;  // the range for random and grid inputs
// Below this reflectivity (linear base colour 0.2%, sRGB 12/255) curves change fastest with r.
constexpr double kDarkReflectivity = 0.002;

// The shaders' basis at the accuracy grid's cosines, evaluated once.
std::vector<std::array<double, 4>> basis_at_cosines(matc::runtime::BasisKind kind) {
  std::vector<std::array<double, 4>> values(matc::kAccuracySamples);
  for (std::size_t j = 0; j < values.size(); ++j) {
    const double mu = static_cast<double>(j) / static_cast<double>(values.size() - 1);
    values[j] = matc::runtime::evaluate_shader_basis(matc::runtime::shipped_shader_basis(kind), mu);
  }
  return values;
}

double channel_f(const ChannelCoefficients& c, const std::array<double, 4>& b) {
  return std::max(0.0, c[0] * b[0] + c[1] * b[1] + c[2] * b[2] + c[3] * b[3]);
}

// One grey (r, g) input: its exact curve on the grid and its per-material compile.
struct Input {
  ArtisticParameters artistic;
  std::vector<double> exact;
  ChannelCoefficients compiled{};
  double compiled_error = 0.0;  // max |F_compiled - exact|
};

std::vector<Input> make_inputs(const std::vector<ArtisticParameters>& parameters,
                               const std::vector<std::array<double, 4>>& basis,
                               matc::runtime::BasisKind kind) {
  std::vector<Input> inputs(parameters.size());
  std::vector<std::future<void>> work;
  constexpr std::size_t kChunk = 64;
  for (std::size_t first = 0; first < inputs.size(); first += kChunk) {
    work.push_back(std::async(std::launch::async, [&, first] {
      for (std::size_t i = first; i < std::min(first + kChunk, inputs.size()); ++i) {
        Input& input = inputs[i];
        input.artistic = parameters[i];
        const matc::ComplexIor ior = matc::gulbrandsen_to_ior(input.artistic);
        const matc::IorCurve curve({ior, ior, ior});
        input.compiled = matc::solve_coefficients(curve, matc::runtime::shipped_basis(kind))[0];
        input.exact.resize(basis.size());
        for (std::size_t j = 0; j < basis.size(); ++j) {
          const double mu = static_cast<double>(j) / static_cast<double>(basis.size() - 1);
          input.exact[j] = matc::fresnel_exact(mu, ior);
          input.compiled_error = std::max(
              input.compiled_error, std::abs(channel_f(input.compiled, basis[j]) - input.exact[j]));
        }
      }
    }));
  }
  for (auto& w : work)
    w.get();
  return inputs;
}

using CoefficientSource = std::function<ChannelCoefficients(double r, double g)>;

struct Design {
  std::string name;
  std::string size;  // bytes of the stored table, or "none"
  CoefficientSource source;
  matc::runtime::BasisKind basis = kBasis;  // scored against this basis' compile
};

struct DesignScore {
  double good_max = 0.0, good_mean = 0.0;  // |F_table - F_compiled| where the compile fits
  double good_max_not_dark = 0.0;          // the same for r >= kDarkReflectivity only
  double poor_excess = 0.0;                // max (table error - compile error) where it does not
  double fbar_max = 0.0, fbar_mean = 0.0;  // |Fbar_table - Fbar_compiled|, through the 128² LUT
};

DesignScore score(const Design& design, const std::vector<Input>& inputs,
                  const std::vector<std::array<double, 4>>& basis, const matc::Lut& lut) {
  DesignScore s;
  double good_sum = 0.0, fbar_sum = 0.0;
  std::size_t good_count = 0, fbar_count = 0;
  for (const Input& input : inputs) {
    const ChannelCoefficients table =
        design.source(input.artistic.reflectivity, input.artistic.edge_tint);
    const bool good = input.compiled_error <= matc::kPoorFitMaxError;
    double table_error = 0.0;
    double good_max = 0.0;
    for (std::size_t j = 0; j < basis.size(); ++j) {
      const double f_table = channel_f(table, basis[j]);
      table_error = std::max(table_error, std::abs(f_table - input.exact[j]));
      if (good) {
        const double d = std::abs(f_table - channel_f(input.compiled, basis[j]));
        s.good_max = std::max(s.good_max, d);
        good_max = std::max(good_max, d);
        good_sum += d;
        ++good_count;
      }
    }
    if (!good) {
      s.poor_excess = std::max(s.poor_excess, table_error - input.compiled_error);
      continue;  // Fbar is compared where F is
    }
    if (input.artistic.reflectivity >= kDarkReflectivity)
      s.good_max_not_dark = std::max(s.good_max_not_dark, good_max);
    for (int a = 0; a <= 16; ++a) {
      for (int b = 0; b <= 16; ++b) {
        const auto bbar = matc::runtime::sample_lut(lut.view(), a / 16.0, b / 16.0);
        const double d = std::abs(channel_f(table, bbar) - channel_f(input.compiled, bbar));
        s.fbar_max = std::max(s.fbar_max, d);
        fbar_sum += d;
        ++fbar_count;
      }
    }
  }
  s.good_mean = good_sum / static_cast<double>(std::max<std::size_t>(good_count, 1));
  s.fbar_mean = fbar_sum / static_cast<double>(fbar_count);
  return s;
}

CoefficientSource from_table(CoefficientTable table) {
  return [table = std::move(table)](double r, double g) {
    return matc::channel_coefficients(table, r, g);
  };
}

// A closed form with no fetch: (c_2, c_3) as polynomials of total degree `degree` in the shipped
// table's axes (u, v), least-squares fitted to a 128² table's texels.
CoefficientSource closed_form(const CoefficientTable& table, int degree) {
  std::vector<std::pair<int, int>> powers;
  for (int total = 0; total <= degree; ++total)
    for (int i = 0; i <= total; ++i)
      powers.emplace_back(i, total - i);
  const auto monomials = [powers](double u, double g) {
    Eigen::RowVectorXd row(static_cast<Eigen::Index>(powers.size()));
    for (std::size_t m = 0; m < powers.size(); ++m)
      row(static_cast<Eigen::Index>(m)) =
          std::pow(u, powers[m].first) * std::pow(g, powers[m].second);
    return row;
  };
  const std::size_t n = table.size();
  Eigen::MatrixXd design(static_cast<Eigen::Index>(n * n),
                         static_cast<Eigen::Index>(powers.size()));
  Eigen::MatrixXd values(static_cast<Eigen::Index>(n * n), 2);
  for (std::size_t y = 0; y < n; ++y) {
    for (std::size_t x = 0; x < n; ++x) {
      const auto row = static_cast<Eigen::Index>(y * n + x);
      design.row(row) = monomials(static_cast<double>(x) / static_cast<double>(n - 1),
                                  static_cast<double>(y) / static_cast<double>(n - 1));
      values(row, 0) = table.texels[2 * (y * n + x)];
      values(row, 1) = table.texels[2 * (y * n + x) + 1];
    }
  }
  const Eigen::MatrixXd fit = design.colPivHouseholderQr().solve(values);
  return [fit, monomials](double r, double g) {
    const double reflectivity = std::clamp(r, 0.0, 1.0);
    const Eigen::RowVectorXd row =
        monomials(matc::runtime::coefficient_table_u_from_reflectivity(reflectivity),
                  matc::runtime::coefficient_table_v_from_edge_tint(g));
    return ChannelCoefficients{reflectivity, 1.0 - reflectivity, (row * fit.col(0))(0),
                               (row * fit.col(1))(0)};
  };
}

std::vector<Design> designs() {
  using matc::EdgeTintAxis;
  using matc::ReflectivityAxis;
  using matc::TableSolve;
  using matc::TableValues;
  const auto table = [](std::size_t size, ReflectivityAxis axis, EdgeTintAxis edge_tint_axis,
                        TableValues values, TableSolve solve,
                        double first_column_offset = matc::kDefaultFirstColumnOffset) {
    return matc::fit_coefficient_table(
        kBasis,
        CoefficientTableOptions{size, axis, edge_tint_axis, values, solve, first_column_offset});
  };
  const auto kib = [](std::size_t size, std::size_t bytes) {
    return fmt::format("{:g} KiB", static_cast<double>(size * size * 2 * bytes) / 1024.0);
  };
  constexpr auto kColumns = ReflectivityAxis::fourth_root_plus_square;
  constexpr auto kRows = EdgeTintAxis::complement_square_root;
  constexpr auto kRaw = TableValues::raw;
  constexpr auto kMinimax = TableSolve::basis;
  constexpr std::size_t kShipped = matc::kDefaultCoefficientTableSize;
  constexpr const char* kColumnsName = "(r^(1/4) + r²) / 2";
  constexpr const char* kRowsName = "1 - sqrt(1 - g)";
  std::vector<Design> all;
  // The shipped layout at several sizes, then one change at a time.
  for (const std::size_t size : {32u, 64u, 96u, 112u, 128u}) {
    all.push_back({fmt::format("{}², {}, {}, c_2 c_3, minimax, f32", size, kColumnsName, kRowsName),
                   kib(size, 4), from_table(table(size, kColumns, kRows, kRaw, kMinimax))});
  }
  const CoefficientTable shipped = table(kShipped, kColumns, kRows, kRaw, kMinimax);
  all.push_back({fmt::format("{}², {}, {}, c_2 c_3, minimax, **f16** (shipped)", kShipped,
                             kColumnsName, kRowsName),
                 kib(kShipped, 2), from_table(matc::stored_as(shipped, matc::LutPrecision::f16))});
  all.push_back({fmt::format("{}², **r^(1/3)**, **log n**, c_2 c_3, minimax, f32 (the former axes: "
                             "a cube root, two log2 and three divisions a channel)",
                             kShipped),
                 kib(kShipped, 4),
                 from_table(table(kShipped, ReflectivityAxis::cube_root, EdgeTintAxis::log_ior,
                                  kRaw, kMinimax))});
  for (const auto& [axis, name] :
       {std::pair{ReflectivityAxis::cube_root, "r^(1/3)"},
        std::pair{ReflectivityAxis::fourth_root, "r^(1/4)"},
        std::pair{ReflectivityAxis::square_root, "sqrt r"},
        std::pair{ReflectivityAxis::stretched_square_root, "2s / (1 + s), s = sqrt r"},
        std::pair{ReflectivityAxis::linear, "r"}}) {
    all.push_back({fmt::format("{}², **{}**, {}, c_2 c_3, minimax, f32", kShipped, name, kRowsName),
                   kib(kShipped, 4), from_table(table(kShipped, axis, kRows, kRaw, kMinimax))});
  }
  all.push_back(
      {fmt::format("{}², **sqrt r**, {}, c_2 c_3, minimax, f32, **first column solved a "
                   "quarter texel in**",
                   kShipped, kRowsName),
       kib(kShipped, 4),
       from_table(table(kShipped, ReflectivityAxis::square_root, kRows, kRaw, kMinimax, 0.25))});
  for (const auto& [axis, name] :
       {std::pair{EdgeTintAxis::log_ior, "log n"}, std::pair{EdgeTintAxis::linear, "g"},
        std::pair{EdgeTintAxis::inverse_ior, "1/n"},
        std::pair{EdgeTintAxis::complement_fourth_root, "1 - (1 - g)^(1/4)"},
        std::pair{EdgeTintAxis::complement_eighth_root, "1 - (1 - g)^(1/8)"}}) {
    all.push_back(
        {fmt::format("{}², {}, **{}**, c_2 c_3, minimax, f32", kShipped, kColumnsName, name),
         kib(kShipped, 4), from_table(table(kShipped, kColumns, axis, kRaw, kMinimax))});
  }
  all.push_back({fmt::format("{}², {}, {}, **(c_2 c_3) / (1 - r)**, minimax, f32", kShipped,
                             kColumnsName, kRowsName),
                 kib(kShipped, 4),
                 from_table(table(kShipped, kColumns, kRows, TableValues::normalised, kMinimax))});
  all.push_back({fmt::format("{}², {}, {}, c_2 c_3, **least squares**, f32", kShipped, kColumnsName,
                             kRowsName),
                 kib(kShipped, 4),
                 from_table(table(kShipped, kColumns, kRows, kRaw, TableSolve::least_squares))});
  const matc::runtime::CoefficientTableView paper =
      matc::runtime::shipped_coefficient_table(matc::runtime::BasisKind::paper);
  all.push_back({fmt::format("{}², {}, {}, c_2 c_3, probes, f32: the **paper basis**' "
                             "table against its own compile",
                             paper.size, kColumnsName, kRowsName),
                 kib(paper.size, 4),
                 [paper](double r, double g) {
                   return matc::runtime::channel_coefficients_from_table(paper, r, g);
                 },
                 matc::runtime::BasisKind::paper});
  for (const int degree : {6, 12})
    all.push_back({fmt::format("closed form: degree {} in the table's axes, no fetch", degree),
                   "none", closed_form(shipped, degree)});
  return all;
}

std::vector<ArtisticParameters> random_parameters() {
  std::vector<ArtisticParameters> out;
  for (const auto& [r, g] : random_artistic_inputs(2000, kMaxReflectivity))
    out.push_back({r, g});
  return out;
}

// Near-black metals, where curves change fastest with r: 100 reflectivities log-spaced over
// [1e-5, kDarkReflectivity] by 11 edge tints.
std::vector<ArtisticParameters> dark_parameters() {
  std::vector<ArtisticParameters> out;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j <= 10; ++j)
      out.push_back({1e-5 * std::pow(kDarkReflectivity / 1e-5, i / 99.0), j / 10.0});
  return out;
}

// A 50 x 50 grid over r in [0, 0.95] (uniform in r, so mostly between texel columns) and g.
std::vector<ArtisticParameters> grid_parameters() {
  std::vector<ArtisticParameters> out;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 50; ++j)
      out.push_back({kMaxReflectivity * i / 49.0, j / 49.0});
  return out;
}

// Per shipped basis: its shader basis at the cosines, its 128² table, and the compiled inputs.
struct BasisInputs {
  std::vector<std::array<double, 4>> basis;
  matc::Lut lut;
  std::vector<Input> random_inputs;
  std::vector<Input> grid_inputs;
  std::vector<Input> dark_inputs;

  explicit BasisInputs(matc::runtime::BasisKind kind)
      : basis(basis_at_cosines(kind)),
        lut(matc::preintegrate_lut(matc::runtime::shipped_basis(kind))),
        random_inputs(make_inputs(random_parameters(), basis, kind)),
        grid_inputs(make_inputs(grid_parameters(), basis, kind)),
        dark_inputs(make_inputs(dark_parameters(), basis, kind)) {}
};

void print_designs() {
  const BasisInputs default_basis(kBasis);
  const BasisInputs paper(matc::runtime::BasisKind::paper);
  fmt::print(
      "| table | stored | 2,000 random: F max / mean | F max, r >= {0} | poor fits: excess | F̄ "
      "max / mean | 50 x 50 grid: F max / mean | poor fits: excess | F̄ max / mean | r < {0}: "
      "F max |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
      kDarkReflectivity);
  std::vector<std::future<std::string>> rows;
  for (const Design& design : designs()) {
    rows.push_back(std::async(std::launch::async, [&, design] {
      const BasisInputs& inputs_of_basis =
          design.basis == matc::runtime::BasisKind::paper ? paper : default_basis;
      std::string row = fmt::format("| {} | {} |", design.name, design.size);
      for (const auto* inputs : {&inputs_of_basis.random_inputs, &inputs_of_basis.grid_inputs}) {
        const DesignScore s = score(design, *inputs, inputs_of_basis.basis, inputs_of_basis.lut);
        row += fmt::format(" {:.5f} / {:.1e} |", s.good_max, s.good_mean);
        if (inputs == &inputs_of_basis.random_inputs)
          row += fmt::format(" {:.5f} |", s.good_max_not_dark);
        row += fmt::format(" {:.4f} | {:.5f} / {:.1e} |", s.poor_excess, s.fbar_max, s.fbar_mean);
      }
      const DesignScore dark =
          score(design, inputs_of_basis.dark_inputs, inputs_of_basis.basis, inputs_of_basis.lut);
      row += fmt::format(" {:.5f} |", dark.good_max);
      return row + "\n";
    }));
  }
  for (auto& row : rows)
    fmt::print("{}", row.get());
}

struct SetScore {
  double compile_worst = 0.0, compile_mean = 0.0;
  double table_worst = 0.0, table_mean = 0.0;
  double artistic_worst = 0.0;  // Gulbrandsen's curve of the fitted (r, g) alone
};

std::string set_row(const TestSet& set) {
  const auto& shader_basis = matc::runtime::shipped_shader_basis(kBasis);
  const matc::runtime::CoefficientTableView table =
      matc::runtime::shipped_coefficient_table(kBasis);
  SetScore s;
  std::size_t count = 0;
  for (const TestCurve& curve : set.curves) {
    const auto compiled =
        matc::solve_coefficients(*curve.cached, matc::runtime::shipped_basis(kBasis));
    const matc::FitAccuracy compile_accuracy =
        matc::measure_accuracy(*curve.cached, compiled, shader_basis);
    const bool measured = !curve.artistic;
    const std::array<ArtisticParameters, 3> artistic =
        measured ? matc::bench::gulbrandsen_look(*curve.cached) : *curve.artistic;
    matc::runtime::Coefficients from_table{};
    for (std::size_t c = 0; c < 3; ++c) {
      from_table[c] = matc::runtime::channel_coefficients_from_table(
          table, artistic[c].reflectivity, artistic[c].edge_tint);
    }
    const matc::FitAccuracy table_accuracy =
        matc::measure_accuracy(*curve.cached, from_table, shader_basis);
    if (measured) {
      const matc::IorCurve gulbrandsen({matc::gulbrandsen_to_ior(artistic[0]),
                                        matc::gulbrandsen_to_ior(artistic[1]),
                                        matc::gulbrandsen_to_ior(artistic[2])});
      for (std::size_t j = 0; j <= 200; ++j) {
        const double mu = static_cast<double>(j) / 200.0;
        const matc::Rgb a = gulbrandsen.at(mu), e = curve.cached->at(mu);
        for (std::size_t c = 0; c < 3; ++c)
          s.artistic_worst = std::max(s.artistic_worst, std::abs(a[c] - e[c]));
      }
    }
    for (std::size_t c = 0; c < curve.channels; ++c) {
      s.compile_worst = std::max(s.compile_worst, compile_accuracy.decomposition.max_abs[c]);
      s.compile_mean += compile_accuracy.decomposition.max_abs[c];
      s.table_worst = std::max(s.table_worst, table_accuracy.decomposition.max_abs[c]);
      s.table_mean += table_accuracy.decomposition.max_abs[c];
      ++count;
    }
  }
  s.compile_mean /= static_cast<double>(count);
  s.table_mean /= static_cast<double>(count);
  const bool measured = !set.curves.empty() && !set.curves.front().artistic;
  return fmt::format("| {} | {:.4f} / {:.4f} | {:.4f} / {:.4f} | {} |\n", set.name, s.compile_worst,
                     s.compile_mean, s.table_worst, s.table_mean,
                     measured ? fmt::format("{:.4f}", s.artistic_worst) : "exact");
}

// Conductors given as n + ik, through the shaders' inverse mapping (matc_artistic_from_ior).
std::string ior_row() {
  const auto& shader_basis = matc::runtime::shipped_shader_basis(kBasis);
  const auto table = matc::runtime::shipped_coefficient_table(kBasis);
  double compile_worst = 0.0, compile_mean = 0.0, table_worst = 0.0, table_mean = 0.0;
  std::size_t count = 0, clamped = 0;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      const double n = 0.05 * std::pow(4.0 / 0.05, i / 19.0);
      const double k = 1.0 + 7.0 * j / 19.0;
      const matc::ComplexIor ior{n, k};
      const matc::IorCurve exact({ior, ior, ior});
      const matc::AccuracyGridCurve curve(exact);
      const auto compiled = matc::solve_coefficients(curve, matc::runtime::shipped_basis(kBasis));
      const auto artistic = matc::runtime::artistic_from_ior({n, n, n}, {k, k, k});
      if (matc::ior_to_gulbrandsen(ior).edge_tint > 1.0) ++clamped;
      const auto from_table =
          matc::runtime::coefficients_from_table(table, artistic.reflectivity, artistic.edge_tint);
      const double c =
          matc::measure_accuracy(curve, compiled, shader_basis).decomposition.max_abs[0];
      const double t =
          matc::measure_accuracy(curve, from_table, shader_basis).decomposition.max_abs[0];
      compile_worst = std::max(compile_worst, c);
      table_worst = std::max(table_worst, t);
      compile_mean += c;
      table_mean += t;
      ++count;
    }
  }
  return fmt::format(
      "| conductors n + ik, n 0.05-4 (log), k 1-8 (20 x 20; {} with g > 1, clamped) | {:.4f} / "
      "{:.4f} | {:.4f} / {:.4f} | exact |\n",
      clamped, compile_worst, compile_mean / static_cast<double>(count), table_worst,
      table_mean / static_cast<double>(count));
}

void print_test_sets() {
  fmt::print(
      "| test set | per-material compile | table path | Gulbrandsen (r, g) alone |\n"
      "|---|---:|---:|---:|\n");
  const std::vector<TestSet> sets = study_test_sets(MATC_ALT_IOR_DIR);
  std::vector<std::future<std::string>> rows;
  for (const TestSet& set : sets)
    rows.push_back(std::async(std::launch::async, [&set] { return set_row(set); }));
  rows.push_back(std::async(std::launch::async, ior_row));
  for (auto& row : rows)
    fmt::print("{}", row.get());
}

}  // namespace

int main(int argc, char** argv) {
  const bool designs_only = argc > 1 && std::string(argv[1]) == "--designs-only";
  const bool sets_only = argc > 1 && std::string(argv[1]) == "--test-sets";
  if (!sets_only) print_designs();
  if (designs_only) return 0;
  if (!sets_only) fmt::print("\n");
  print_test_sets();
  return 0;
}
