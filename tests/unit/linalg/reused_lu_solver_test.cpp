// ReusedLuSolver: a matrix that differs from the factorised one by rank k is solved by GMRES
// on the old factors in about k + 1 iterations, to the acceptance tolerance, without a new
// factorisation; an unrelated matrix, or one after reset(), is factorised afresh; a looser
// acceptance (the forcing term of an inexact Newton step) ends only the expensive solves.
#include "fem/linalg/reused_lu_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

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

TEST(ReusedLuSolver, LooserAcceptanceOnlyForExpensiveSolves) {
  const int n = 150;
  const Eigen::MatrixXd J0 = test_matrix(n, 3);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  // A change of rank 2 is cheap (about 3 iterations): solved to the tight acceptance even
  // when the caller would take 1e-3, so Newton keeps its finite termination.
  {
    ReusedLuSolver solver;
    solver.solve(J0, b);
    Eigen::MatrixXd J = J0;
    J.row(5) *= 3.0;
    J.row(90) = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0).transpose();
    const Eigen::VectorXd x = solver.solve(J, b, 1e-3);
    EXPECT_LE(solver.last_iterations(), ReusedLuSolver::cheap_iterations);
    EXPECT_LT(relative_residual(J, x, b), 1e-11);
  }
  // A full-rank perturbation (about 30 % of the matrix) needs more than the cheap iterations
  // for 1e-11; with 1e-3 accepted the solve stops there, its residual within 1e-3.
  std::srand(4);
  const Eigen::MatrixXd J = J0 + 0.3 * std::sqrt(n) * Eigen::MatrixXd::Random(n, n);
  int tight_iterations = 0;
  for (double accept : {1e-11, 1e-3}) {
    ReusedLuSolver solver;
    solver.solve(J0, b);
    const Eigen::VectorXd x = solver.solve(J, b, accept);
    std::printf("accept %.0e: %d GMRES iterations, residual %.1e\n", accept,
                solver.last_iterations(), relative_residual(J, x, b));
    EXPECT_EQ(solver.factorizations(), 1) << "accept " << accept;
    EXPECT_LE(relative_residual(J, x, b), accept) << "accept " << accept;
    if (accept == 1e-11) {
      tight_iterations = solver.last_iterations();
      EXPECT_GT(tight_iterations, ReusedLuSolver::cheap_iterations);
    } else {
      EXPECT_EQ(solver.last_iterations(), ReusedLuSolver::cheap_iterations);
    }
  }
}

} // namespace
} // namespace bipot
