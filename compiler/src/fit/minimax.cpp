#include "fit/minimax.h"

namespace matc {

Eigen::VectorXd near_minimax_fit(const Eigen::MatrixXd& design, const Eigen::VectorXd& values,
                                 int iterations) {
  Eigen::VectorXd weights = Eigen::VectorXd::Ones(values.size());
  Eigen::VectorXd solution;
  for (int iteration = 0; iteration <= iterations; ++iteration) {
    solution =
        (weights.asDiagonal() * design).colPivHouseholderQr().solve(weights.asDiagonal() * values);
    const Eigen::VectorXd error = (design * solution - values).cwiseAbs();
    weights = weights.cwiseProduct((error.array() + 1e-15).sqrt().matrix());
    weights /= weights.maxCoeff();
  }
  return solution;
}

}  // namespace matc
