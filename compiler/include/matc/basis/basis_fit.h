// Fitting the Fresnel basis b_1..b_3 from a training set of exact curves (Belcour et al. 2020).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "matc/runtime/basis.h"
#include "matc/runtime/basis_polynomial.h"

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
  // The shaders' form of the tables (fit_basis_polynomial).
  runtime::BasisPolynomial polynomial{};

  runtime::BasisView view() const;
};

// Each curve is normalised to (F - F0) / (1 - F0). b_1 = |first right singular vector| scaled to
// max 1; b_2, b_3 = first two right singular vectors of the residual (normalised curve - b_1),
// each scaled so that its largest-magnitude entry is +1. Probes: mu_1 = argmax b_2, mu_2 = the
// extremum of b_3 farther from mu_1. The polynomial form is fitted to the resulting tables.
FittedBasis fit_paper_basis(const PaperBasisOptions& options = {});

// The C++ source of runtime/src/paper_basis_table.cpp for `basis` (what `matc basis fit` writes).
std::string basis_table_source(const FittedBasis& basis, const PaperBasisOptions& options);

}  // namespace matc
