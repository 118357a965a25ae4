// Near-minimax linear fits (internal: Eigen stays out of the public headers), used for the basis'
// shader polynomials and the coefficient solve.
#pragma once

#include <Eigen/Dense>

namespace matc {

// Lawson's algorithm: least squares whose sample weights are repeatedly multiplied by the
// (square-rooted, for damping) error drives the solution towards the one minimising the largest
// |design * x - values|. `iterations` = 0 is plain least squares.
Eigen::VectorXd near_minimax_fit(const Eigen::MatrixXd& design, const Eigen::VectorXd& values,
                                 int iterations = 40);

}  // namespace matc
