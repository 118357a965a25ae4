#include "matc/runtime/basis.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "matc/runtime/shipped_bases.h"

namespace matc::runtime {

std::string_view basis_name(BasisKind kind) {
  return shipped_basis_record(kind).name;
}

std::optional<BasisKind> basis_from_name(std::string_view name) {
  for (const BasisKind kind : kShippedBases)
    if (basis_name(kind) == name) return kind;
  return std::nullopt;
}

std::string per_material_basis_names() {
  std::string names;
  for (const BasisKind kind : kPerMaterialBases)
    names.append(names.empty() ? "" : ", ").append(basis_name(kind));
  return names;
}

BasisView shipped_basis(BasisKind kind) {
  return shipped_basis_record(kind).table();
}

std::array<double, kBasisSize> BasisView::at_index(std::size_t index) const {
  return {1.0, tables[0][index], tables[1][index], tables[2][index]};
}

std::array<double, kBasisSize> BasisView::evaluate(double mu) const {
  const double last = static_cast<double>(samples() - 1);
  const double position = std::clamp(mu, 0.0, 1.0) * last;
  // Clamp the left index so that mu = 1 interpolates inside the last interval.
  const std::size_t left = std::min(static_cast<std::size_t>(std::floor(position)), samples() - 2);
  const double t = position - static_cast<double>(left);
  std::array<double, kBasisSize> values{1.0, 0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < tables.size(); ++i) {
    values[i + 1] = tables[i][left] + t * (tables[i][left + 1] - tables[i][left]);
  }
  return values;
}

}  // namespace matc::runtime
