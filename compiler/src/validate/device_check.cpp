#include "validate/device_check.h"

#include <algorithm>
#include <stdexcept>

namespace matc {

bool PathResult::passed() const {
  return !quantities.empty() &&
         std::all_of(quantities.begin(), quantities.end(),
                     [](const CheckedQuantity& quantity) { return quantity.passed(); });
}

const CheckedQuantity& PathResult::quantity(std::string_view label) const {
  for (const CheckedQuantity& quantity : quantities)
    if (quantity.label == label) return quantity;
  throw std::out_of_range("no quantity '" + std::string(label) + "' in this check");
}

bool CheckResult::passed() const {
  return !paths.empty() &&
         std::all_of(paths.begin(), paths.end(), [](const PathResult& p) { return p.passed(); });
}

std::vector<std::unique_ptr<DeviceCheck>> shared_file_checks(const Build& build,
                                                             const ValidationTolerance& tolerance) {
  std::vector<std::unique_ptr<DeviceCheck>> checks;
  if (build.options().emit.contains(OutputKind::coefficient_table))
    checks.push_back(coefficient_table_check(build, tolerance));
  if (build.options().emit.contains(OutputKind::ltc))
    checks.push_back(area_light_check(build, tolerance));
  return checks;
}

}  // namespace matc
