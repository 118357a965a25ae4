// The basis study of issue #8 (docs/accuracy.md, "Choosing the basis"): which training set,
// weighting and coefficient solve give the most accurate four-term decomposition, measured on
// curves no fit saw. Every candidate is fitted here from scratch; nothing is read from a table.
//   matc_basis_study [--quick] [--only TEXT]   (bench/accuracy/update-docs.sh runs it in full)
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/core.h>

#include "basis/basis_fit.h"
#include "basis/training_set.h"
#include "fit/accuracy.h"
#include "fit/coefficients.h"
#include "optics/gulbrandsen.h"
#include "optics/presets.h"
#include "optics/spectral.h"
#include "optics/spectrum.h"
#include "study_score.h"
#include "test_sets.h"

namespace {

using matc::ComplexIor;
using matc::FittedBasis;
using matc::ReflectanceCurve;
using matc::Rgb;
using namespace matc::bench;

enum class Solve { probes, talk_probes, least_squares, minimax };

const char* solve_name(Solve solve) {
  switch (solve) {
    case Solve::probes:
      return "probes";
    case Solve::talk_probes:
      return "probes at 1.45, 1.31 rad";
    case Solve::least_squares:
      return "least squares";
    case Solve::minimax:
      return "minimax";
  }
  return "";
}

// The basis with its probes moved to the angles the talk quotes (the notebook's construction,
// argmax b_2 and the farther extremum of b_3, gives about 1.44 and 1.12 rad).
matc::runtime::BasisView with_talk_probes(matc::runtime::BasisView view) {
  const auto index = [&](double theta) {
    return static_cast<std::size_t>(
        std::lround(std::cos(theta) * static_cast<double>(view.samples() - 1)));
  };
  view.probe_indices = {index(1.45), index(1.31)};
  return view;
}

matc::runtime::Coefficients solve_with(Solve solve, const ReflectanceCurve& curve,
                                       const FittedBasis& basis) {
  switch (solve) {
    case Solve::probes:
      return matc::solve_coefficients_at_probes(curve, basis.view());
    case Solve::talk_probes:
      return matc::solve_coefficients_at_probes(curve, with_talk_probes(basis.view()));
    case Solve::least_squares:
      return matc::solve_coefficients_least_squares(curve, basis.shader);
    case Solve::minimax:
      return matc::solve_coefficients_minimax(curve, basis.shader);
  }
  return {};
}

Score score(const TestSet& set, const FittedBasis& basis, Solve solve) {
  return matc::bench::score(
      set, basis, [&](const ReflectanceCurve& curve) { return solve_with(solve, curve, basis); });
}

struct TrainingSet {
  std::string name;
  std::vector<ComplexIor> iors;
};

std::vector<ComplexIor> joined(std::vector<ComplexIor> a, const std::vector<ComplexIor>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<TrainingSet> training_sets() {
  const auto artistic_grid = matc::artistic_training_iors({40, 40, 1.0, 0.0});
  const auto metal_grid = matc::complex_ior_training_iors(matc::kExtendedTrainingGrid);
  const auto some_dielectrics = matc::dielectric_training_iors(100, 1.01, 3.0);
  return {
      {"paper: 990 dielectrics + 10 conductors (g = 1)", matc::paper_training_iors()},
      {"990 dielectrics + 100 conductors (g = 1)", matc::paper_training_iors({1000, 990, 100})},
      {"990 dielectrics + 300 conductors (g = 1)", matc::paper_training_iors({1000, 990, 300})},
      {"artistic r x g grid, 40 x 40", artistic_grid},
      {"conductor n x k grid, 40 x 40", metal_grid},
      {"n x k grid + 100 dielectrics", joined(metal_grid, some_dielectrics)},
      {"n x k grid + r x g grid", joined(metal_grid, artistic_grid)},
      {"paper + n x k grid", joined(matc::paper_training_iors(), metal_grid)},
      {"990 dielectrics + 100 conductors (g = 1) + n x k grid",
       joined(matc::paper_training_iors({1000, 990, 100}), metal_grid)},
      {"n x k grid + 100 conductors (g = 1)",
       joined(matc::artistic_training_iors({100, 1, 1.0, 1.0}), metal_grid)},
      // High-index dielectrics (what g = 0 makes of r above 0.25) trade metal accuracy away.
      {"990 dielectrics (eta 1.01-9) + 100 conductors (g = 1) + n x k grid",
       joined(matc::paper_training_iors({1000, 990, 100, 1.01, 9.0}), metal_grid)},
      {"990 dielectrics + 300 more (eta 3-9) + 100 conductors (g = 1) + n x k grid",
       joined(joined(matc::paper_training_iors({1000, 990, 100}),
                     matc::dielectric_training_iors(300, 3.0, 9.0)),
              metal_grid)},
  };
}

struct Construction {
  std::string name;
  matc::BasisConstruction options;
};

std::vector<Construction> constructions() {
  using matc::CosineWeighting;
  using matc::CurveWeighting;
  using matc::MeanShape;
  std::vector<Construction> all;
  for (const MeanShape shape : {MeanShape::first_singular_vector, MeanShape::mean_curve}) {
    for (const CurveWeighting curves : {CurveWeighting::equal, CurveWeighting::one_minus_f0}) {
      for (const CosineWeighting cosines :
           {CosineWeighting::solid_angle, CosineWeighting::projected_solid_angle}) {
        all.push_back({fmt::format("{}, {}, {}", shape == MeanShape::mean_curve ? "mean" : "SVD",
                                   curves == CurveWeighting::one_minus_f0 ? "1-F0" : "equal",
                                   cosines == CosineWeighting::solid_angle ? "dω" : "μ dω"),
                       {1000, shape, curves, cosines}});
      }
    }
  }
  return all;
}

// The IORs of a measured spectrum every 10 nm over 400-700 nm: how a measured metal joins a
// training set.
std::vector<ComplexIor> spectrum_samples(const matc::Spectrum& spectrum) {
  std::vector<ComplexIor> iors;
  for (int nm = 400; nm <= 700; nm += 10)
    iors.push_back(spectrum.at(nm));
  return iors;
}

Score merged(const std::vector<Score>& parts, const std::vector<std::size_t>& counts) {
  Score result;
  std::size_t total = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    result.worst = std::max(result.worst, parts[i].worst);
    result.mean += parts[i].mean * static_cast<double>(counts[i]);
    total += counts[i];
  }
  result.mean /= static_cast<double>(total);
  return result;
}

// Leave-one-out over the measured metals: each metal is scored on a basis fitted to the shipped
// conductor set plus the spectra of the 22 others, never its own.
std::array<Score, 2> leave_one_out(const matc::BasisConstruction& construction) {
  std::vector<const matc::MetalPreset*> metals;
  for (const matc::MetalPreset& preset : matc::metal_presets())
    if (preset.caveat.empty()) metals.push_back(&preset);
  std::array<std::vector<Score>, 2> parts;
  std::vector<std::size_t> counts;
  for (const matc::MetalPreset* held_out : metals) {
    std::vector<ComplexIor> training = matc::extended_training_iors();
    for (const matc::MetalPreset* other : metals)
      if (other != held_out)
        training = joined(std::move(training), spectrum_samples(matc::preset_spectrum(*other)));
    const FittedBasis basis = matc::fit_basis(training, construction);
    TestSet one{std::string(held_out->symbol), {}};
    one.add(one.name, std::make_unique<matc::SpectralCurve>(matc::preset_spectrum(*held_out)), 3);
    parts[0].push_back(score(one, basis, Solve::probes));
    parts[1].push_back(score(one, basis, Solve::minimax));
    counts.push_back(3);
  }
  return {merged(parts[0], counts), merged(parts[1], counts)};
}

}  // namespace

int main(int argc, char** argv) {
  // --quick: only the shipped construction; --only TEXT: only training sets whose name has TEXT.
  bool quick = false;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument = argv[i];
    if (argument == "--quick") quick = true;
    if (argument == "--only" && i + 1 < argc) only = argv[++i];
  }
  const std::vector<TestSet> tests = study_test_sets(MATC_ALT_IOR_DIR);

  fmt::print("| training set | construction | solve |");
  for (const TestSet& set : tests)
    fmt::print(" {} |", set.name);
  fmt::print("\n|---|---|---|");
  for (std::size_t i = 0; i < tests.size(); ++i)
    fmt::print("---:|");
  fmt::print("\n");

  // Each candidate's rows are computed on their own thread and printed in a fixed order.
  std::vector<std::future<std::string>> rows;
  for (const TrainingSet& training : training_sets()) {
    for (const Construction& construction : constructions()) {
      if (quick && construction.name != "SVD, 1-F0, dω") continue;
      if (training.name.find(only) == std::string::npos) continue;
      rows.push_back(std::async(std::launch::async, [&tests, training, construction] {
        const FittedBasis basis = matc::fit_basis(training.iors, construction.options);
        std::string out;
        for (const Solve solve : {Solve::probes, Solve::minimax}) {
          out +=
              fmt::format("| {} | {} | {} |", training.name, construction.name, solve_name(solve));
          for (const TestSet& set : tests) {
            const Score s = score(set, basis, solve);
            out += fmt::format(" {:.4f} / {:.4f} |", s.worst, s.mean);
          }
          out += "\n";
        }
        return out;
      }));
    }
  }
  for (auto& row : rows)
    fmt::print("{}", row.get());
  if (quick || !only.empty()) return 0;

  const std::array<Score, 2> held_out = leave_one_out(matc::kExtendedConstruction);
  for (const Solve solve : {Solve::probes, Solve::minimax}) {
    const Score s = held_out[solve == Solve::probes ? 0 : 1];
    fmt::print(
        "| 990 dielectrics + 100 conductors (g = 1) + n x k grid + the other 22 metals' spectra "
        "(leave one out) | SVD, 1-F0, dω | {} | {:.4f} / {:.4f} |",
        solve_name(solve), s.worst, s.mean);
    for (std::size_t i = 1; i < tests.size(); ++i)
      fmt::print(" |");
    fmt::print("\n");
  }

  // The coefficient solve on the two shipped constructions: collocation at the basis' own probes
  // or at the talk's angles, least squares, near-minimax.
  fmt::print("\n| basis | solve |");
  for (const TestSet& set : tests)
    fmt::print(" {} |", set.name);
  fmt::print("\n|---|---|");
  for (std::size_t i = 0; i < tests.size(); ++i)
    fmt::print("---:|");
  fmt::print("\n");
  const std::pair<const char*, FittedBasis> shipped[] = {{"paper", matc::fit_paper_basis()},
                                                         {"extended", matc::fit_extended_basis()}};
  for (const auto& [name, basis] : shipped) {
    for (const Solve solve :
         {Solve::probes, Solve::talk_probes, Solve::least_squares, Solve::minimax}) {
      fmt::print("| {} | {} |", name, solve_name(solve));
      for (const TestSet& set : tests) {
        const Score s = score(set, basis, solve);
        fmt::print(" {:.4f} / {:.4f} |", s.worst, s.mean);
      }
      fmt::print("\n");
    }
  }
  return 0;
}
