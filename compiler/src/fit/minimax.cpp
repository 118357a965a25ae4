#include "fit/minimax.h"

namespace matc {

Eigen::VectorXd near_minimax_fit(const Eigen::MatrixXd& design, const Eigen::VectorXd& values,
                                 int iterations) {
  // The weighted system and its factorisation live across the iterations (a compile runs 41 of
  // them per channel): the same arithmetic as building them anew, without the allocations.
  Eigen::VectorXd weights = Eigen::VectorXd::Ones(values.size());
  Eigen::MatrixXd weighted_design(design.rows(), design.cols());
  Eigen::VectorXd weighted_values(values.size());
  Eigen::VectorXd error(values.size());
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> factorisation(design.rows(), design.cols());
  Eigen::VectorXd solution;
  for (int iteration = 0; iteration <= iterations; ++iteration) {
    weighted_design.noalias() = weights.asDiagonal() * design;
    weighted_values.noalias() = weights.asDiagonal() * values;
    solution = factorisation.compute(weighted_design).solve(weighted_values);
    error.noalias() = design * solution;
    error = (error - values).cwiseAbs();
    weights = weights.cwiseProduct((error.array() + 1e-15).sqrt().matrix());
    weights /= weights.maxCoeff();
  }
  return solution;
}

}  // namespace matc
