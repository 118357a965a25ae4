#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "matc/compile.h"
#include "matc/fit/coefficients.h"
#include "matc/json_format.h"
#include "matc/material/parse.h"
#include "print_diagnostics.h"

namespace matc::cli {

int run_eval(const EvalOptions& options) {
  const ParseResult parsed = read_material_file(options.file);
  print_diagnostics(parsed.diagnostics);
  if (!parsed.material) return kExitInputError;

  const runtime::BasisView basis = runtime::paper_basis();
  const auto curve = make_reflectance_curve(*parsed.material);
  const runtime::Coefficients coefficients = solve_coefficients(*curve, basis);

  nlohmann::ordered_json decomposed = nlohmann::ordered_json::array();
  nlohmann::ordered_json exact = nlohmann::ordered_json::array();
  for (const double mu : options.mu) {
    decomposed.push_back(runtime::evaluate_fresnel(coefficients, basis, mu));
    exact.push_back(curve->at(mu));
  }
  nlohmann::ordered_json out;
  out["name"] = parsed.material->name;
  out["mu"] = options.mu;
  out["F"] = std::move(decomposed);
  out["F_exact"] = std::move(exact);
  fmt::print("{}", format_json(out));
  return kExitSuccess;
}

}  // namespace matc::cli
