// Which closed-form basis to ship (issue #28, docs/accuracy.md "A basis in closed form"): bases
// whose elements are integer powers of m = 1 - mu cost a shader a few multiplies where the fitted
// bases' piecewise polynomials cost a hundred instructions. The family studied is
//   b_1 = m^k,   b_2 = mu m^p,   b_3 = mu m^(p + k) = b_2 b_1,
// so that F = c_0 + c_2 b_2 + b_1 (c_1 + c_3 b_2) is three multiply-adds a channel. Each candidate
// is scored with the near-minimax solve on curves no basis was fitted to, beside the fitted bases.
//   matc_closed_form_basis_study   (about 15 s on 2 cores; bench/accuracy/update-docs.sh runs it)
#include <algorithm>
#include <cmath>
#include <future>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "basis/basis_fit.h"
#include "basis/basis_polynomial_fit.h"
#include "fit/accuracy.h"
#include "fit/coefficients.h"
#include "study_score.h"
#include "test_sets.h"

namespace {

using matc::FittedBasis;
using namespace matc::bench;

struct Exponents {
  int k = 0;  // b_1 = m^k
  int p = 0;  // b_2 = mu m^p
};

// A candidate as the solve and the measure see it: its tables sampled from the formula and its
// shader form the piecewise polynomial fitted to them (within 2e-4 of the formula, far below the
// errors compared here); the shipped powers basis is scored through its exact closed form.
FittedBasis candidate(Exponents e) {
  constexpr std::size_t kSamples = 1000;
  FittedBasis basis;
  for (auto& table : basis.tables)
    table.resize(kSamples);
  for (std::size_t j = 0; j < kSamples; ++j) {
    const double mu = static_cast<double>(j) / (kSamples - 1);
    const double m = 1.0 - mu;
    basis.tables[0][j] = std::pow(m, e.k);
    basis.tables[1][j] = mu * std::pow(m, e.p);
    basis.tables[2][j] = mu * std::pow(m, e.p + e.k);
  }
  basis.kind = matc::runtime::BasisKind::extended;  // near-minimax coefficients
  basis.shader = matc::fit_basis_polynomial(basis.view());
  return basis;
}

Score score(const TestSet& set, const FittedBasis& basis) {
  return matc::bench::score(set, basis, [&](const matc::ReflectanceCurve& curve) {
    return matc::solve_coefficients_minimax(curve, basis.shader);
  });
}

std::string row(const std::string& name, const std::vector<TestSet>& sets,
                const FittedBasis& basis) {
  std::string out = fmt::format("| {} |", name);
  for (const TestSet& set : sets) {
    const Score s = score(set, basis);
    out += fmt::format(" {:.4f} / {:.4f} |", s.worst, s.mean);
  }
  return out + "\n";
}

void header(const std::string& first, const std::vector<TestSet>& sets) {
  fmt::print("| {} |", first);
  for (const TestSet& set : sets)
    fmt::print(" {} |", set.name);
  fmt::print("\n|---|");
  for (std::size_t i = 0; i < sets.size(); ++i)
    fmt::print("---:|");
  fmt::print("\n");
}

}  // namespace

int main() {
  // The sweep: measured metals and 200 random artistic metals (r <= 0.8), worst / mean of the
  // per-curve max error, for k in 4..9 and p in 2..5; rows sorted by the metals' mean.
  std::vector<TestSet> sweep_sets;
  sweep_sets.push_back(measured_metals());
  sweep_sets.push_back(artistic(200, 0.8));
  std::vector<std::future<std::pair<double, std::string>>> rows;
  for (int k = 4; k <= 9; ++k) {
    for (int p = 2; p <= 5; ++p) {
      rows.push_back(std::async(std::launch::async, [&sweep_sets, k, p] {
        const FittedBasis basis = candidate({k, p});
        const double mean = score(sweep_sets[0], basis).mean;
        return std::pair{
            mean, row(fmt::format("m^{}, mu m^{}, mu m^{}", k, p, k + p), sweep_sets, basis)};
      }));
    }
  }
  std::vector<std::pair<double, std::string>> sorted;
  for (auto& r : rows)
    sorted.push_back(r.get());
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  header("b_1, b_2, b_3", sweep_sets);
  for (std::size_t i = 0; i < std::min<std::size_t>(sorted.size(), 10); ++i)
    fmt::print("{}", sorted[i].second);

  // The finalists on every study set, beside the fitted bases (each with near-minimax
  // coefficients) and the authors' basis with its own probe solve (from the basis study).
  const std::vector<TestSet> sets = study_test_sets(MATC_ALT_IOR_DIR);
  fmt::print("\n");
  header("basis", sets);
  fmt::print("{}", row("**shipped `powers`**: m^6, mu m^3, mu m^9 (closed form)", sets,
                       matc::closed_form_fitted_basis(matc::runtime::BasisKind::powers)));
  for (const Exponents e : {Exponents{5, 4}, Exponents{8, 4}, Exponents{7, 4}}) {
    fmt::print("{}",
               row(fmt::format("m^{}, mu m^{}, mu m^{}", e.k, e.p, e.k + e.p), sets, candidate(e)));
  }
  fmt::print("{}",
             row("`extended` (fitted, the former default)", sets, matc::fit_extended_basis()));
  fmt::print("{}",
             row("`paper` (fitted), near-minimax coefficients", sets, matc::fit_paper_basis()));
  return 0;
}
