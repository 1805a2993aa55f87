// ReusedLuSolver: a matrix that differs from the factorised one by rank k is solved by GMRES
// on the old factors in about k + 1 iterations, to the acceptance tolerance, without a new
// factorisation; an unrelated matrix, or one after reset(), is factorised afresh.
#include "fem/linalg/reused_lu_solver.hpp"

#include <gtest/gtest.h>

namespace bipot {
namespace {

// A well-conditioned nonsymmetric matrix (diagonally dominant), deterministic.
Eigen::MatrixXd test_matrix(int n, unsigned seed) {
  std::srand(seed);
  return Eigen::MatrixXd::Random(n, n) + n * Eigen::MatrixXd::Identity(n, n);
}

double relative_residual(const Eigen::MatrixXd& J, const Eigen::VectorXd& x,
                         const Eigen::VectorXd& b) {
  return (J * x - b).norm() / b.norm();
}

TEST(ReusedLuSolver, LowRankChangesAreSolvedOnTheOldFactors) {
  const int n = 200, k = 6;
  ReusedLuSolver solver; // accept 1e-11
  Eigen::MatrixXd J = test_matrix(n, 1);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  Eigen::VectorXd x = solver.solve(J, b);
  EXPECT_EQ(solver.factorizations(), 1);
  EXPECT_LT(relative_residual(J, x, b), 1e-13);
  // Rows of k pairs change (as when k pairs switch between stick and slip).
  for (int i = 0; i < k; ++i)
    J.row(7 * i + 3) = Eigen::VectorXd::LinSpaced(n, 0.5 * i, n + 1.0).transpose();
  x = solver.solve(J, b);
  EXPECT_EQ(solver.factorizations(), 1);
  EXPECT_LE(solver.last_iterations(), 3 * (k + 2)); // refinement passes included
  EXPECT_LT(relative_residual(J, x, b), 1e-11);
}

TEST(ReusedLuSolver, UnrelatedMatricesAndResetFactoriseAgain) {
  const int n = 120;
  ReusedLuSolver solver(1e-12, 1e-11, 10); // at most 10 GMRES iterations
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  solver.solve(test_matrix(n, 1), b);
  // A full-rank change needs ~n iterations: more than allowed, so a new factorisation.
  const Eigen::MatrixXd other = test_matrix(n, 2).transpose() * 3.0;
  const Eigen::VectorXd x = solver.solve(other, b);
  EXPECT_EQ(solver.factorizations(), 2);
  EXPECT_LT(relative_residual(other, x, b), 1e-13);
  solver.reset();
  solver.solve(other, b);
  EXPECT_EQ(solver.factorizations(), 3);
  EXPECT_EQ(solver.last_iterations(), 0);
}

} // namespace
} // namespace bipot
