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

// J = [−S 0; 0 0] + P as generalized_newton builds it: S dense on the first m unknowns, P
// sparse (a few entries per row, the multiplier rows' identity-like diagonal), seeded.
CondensedNewtonMatrix condensed(const Eigen::MatrixXd& S, int n, unsigned seed, double scale) {
  CondensedNewtonMatrix J(S, n);
  std::vector<Eigen::Triplet<double>> entries;
  std::srand(seed);
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, i < S.rows() ? 0.0 : 1.0);
    for (int k = 0; k < 3; ++k)
      entries.emplace_back(i, std::rand() % n, scale * (std::rand() / double(RAND_MAX) - 0.5));
  }
  J.set_sparse_part(entries);
  return J;
}

TEST(ReusedLuSolver, OperatorFormGivesTheDenseSolution) {
  const int m = 120, n = 180;
  const Eigen::MatrixXd S = -test_matrix(m, 5); // −S then dominates the top-left block
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -2.0, 1.0);
  // The dense form of the operator is −S in the corner plus P.
  const CondensedNewtonMatrix J0 = condensed(S, n, 6, 1.0);
  Eigen::MatrixXd dense0;
  J0.to_dense(dense0);
  Eigen::MatrixXd expected = Eigen::MatrixXd(J0.sparse_part());
  expected.topLeftCorner(m, m) -= S;
  EXPECT_EQ((dense0 - expected).norm(), 0.0);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, 0.5, -0.5);
  EXPECT_LE((J0 * x - dense0 * x).norm(), 1e-13 * (dense0 * x).norm());
  // A sequence (factorise, then GMRES on the old factors for a changed P), once in operator
  // form and once with the dense matrices: the same solutions to round-off.
  const CondensedNewtonMatrix J1 = condensed(S, n, 7, 3.0);
  Eigen::MatrixXd dense1;
  J1.to_dense(dense1);
  ReusedLuSolver by_operator, by_dense;
  for (const auto* J : {&J0, &J1}) {
    const Eigen::MatrixXd& dense = J == &J0 ? dense0 : dense1;
    const Eigen::VectorXd xo = by_operator.solve(*J, b, 1e-11);
    const Eigen::VectorXd xd = by_dense.solve(dense, b, 1e-11);
    const Eigen::VectorXd exact = dense.partialPivLu().solve(b);
    std::printf("operator form: %d GMRES iterations (dense %d), |xo - xd| / |xd| = %.1e\n",
                by_operator.last_iterations(), by_dense.last_iterations(),
                (xo - xd).norm() / xd.norm());
    EXPECT_LE((xo - xd).norm(), 1e-12 * xd.norm());
    EXPECT_LE((xo - exact).norm(), 1e-10 * exact.norm());
    EXPECT_LT(relative_residual(dense, xo, b), 1e-11);
    EXPECT_EQ(by_operator.last_iterations(), by_dense.last_iterations());
  }
  EXPECT_EQ(by_operator.factorizations(), 1); // the second matrix ran on the first's factors
  EXPECT_GT(by_operator.last_iterations(), 0);
}

TEST(ReusedLuSolver, SymmetricBlockIsReadByItsLowerTriangle) {
  const int m = 90, n = 130;
  Eigen::MatrixXd S = test_matrix(m, 12);
  S = -(S + S.transpose()).eval();
  const CondensedNewtonMatrix full = condensed(S, n, 13, 1.0);
  Eigen::MatrixXd dense_full, dense_lower;
  full.to_dense(dense_full);
  // The same P: copy it over.
  std::vector<Eigen::Triplet<double>> entries;
  for (int c = 0; c < full.sparse_part().outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(full.sparse_part(), c); it; ++it)
      entries.emplace_back(it.row(), it.col(), it.value());
  CondensedNewtonMatrix by_lower(S, n, true);
  by_lower.set_sparse_part(entries);
  by_lower.to_dense(dense_lower);
  EXPECT_EQ((dense_lower - dense_full).norm(), 0.0);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
  EXPECT_LE((by_lower * x - dense_full * x).norm(), 1e-13 * (dense_full * x).norm());
  // Only the lower triangle is read: an upper triangle of garbage changes nothing.
  Eigen::MatrixXd S_upper_garbage = S;
  S_upper_garbage.triangularView<Eigen::StrictlyUpper>().setConstant(1e30);
  CondensedNewtonMatrix garbage(S_upper_garbage, n, true);
  garbage.set_sparse_part(entries);
  EXPECT_LE((garbage * x - dense_full * x).norm(), 1e-13 * (dense_full * x).norm());
}

TEST(ReusedLuSolver, OperatorFormStopsAtTheForcingTerm) {
  const int m = 100, n = 150;
  const Eigen::MatrixXd S = -test_matrix(m, 8);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const CondensedNewtonMatrix J0 = condensed(S, n, 9, 1.0);
  // Every row of P changed: beyond the cheap iterations, within GMRES' maximum.
  const CondensedNewtonMatrix J1 = condensed(S, n, 10, 3.0);
  Eigen::MatrixXd dense1;
  J1.to_dense(dense1);
  int tight_iterations = 0;
  for (double eta : {1e-11, 1e-3}) {
    ReusedLuSolver solver;
    solver.solve(J0, b, 1e-11);
    const Eigen::VectorXd x = solver.solve(J1, b, eta);
    const double residual = relative_residual(dense1, x, b);
    std::printf("eta %.0e: %d GMRES iterations, residual %.1e\n", eta, solver.last_iterations(),
                residual);
    EXPECT_EQ(solver.factorizations(), 1) << eta;
    EXPECT_LE(residual, eta) << eta;
    if (eta == 1e-11) {
      tight_iterations = solver.last_iterations();
      EXPECT_GT(tight_iterations, ReusedLuSolver::cheap_iterations);
    } else {
      // Stopped early: fewer iterations than the tight solve, and a residual above its.
      EXPECT_LT(solver.last_iterations(), tight_iterations);
      EXPECT_GT(residual, 1e-11);
    }
  }
}

// n = 600: three tiles of the substitutions, so with 2 ranks GMRES' preconditioner runs on
// factors shared by the ranks (SplitTriangularSolve). A change of rank k in P is still solved
// on the old factors in about k + 1 iterations; a wrong shared substitution would need ~n
// iterations and a new factorisation.
TEST(ReusedLuSolver, SharedSubstitutionsPreconditionAsTheWholeFactors) {
  const int m = 400, n = 600, k = 5;
  Eigen::MatrixXd S = test_matrix(m, 14);
  S = -(S + S.transpose()).eval(); // symmetric, as a linear bulk's
  const CondensedNewtonMatrix P0 = condensed(S, n, 15, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  for (int c = 0; c < P0.sparse_part().outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(P0.sparse_part(), c); it; ++it)
      entries.emplace_back(it.row(), it.col(), it.value());
  CondensedNewtonMatrix J0(S, n, true), J1(S, n, true);
  J0.set_sparse_part(entries);
  for (int i = 0; i < k; ++i) // k rows change (pairs switching status)
    entries.emplace_back(m + 37 * i, 11 * i, 5.0 + i);
  J1.set_sparse_part(entries);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  for (const bool single : {true, false}) {
    ReusedLuSolver solver;
    solver.set_single_precision_factors(single);
    solver.solve(J0, b, 1e-11);
    const Eigen::VectorXd x = solver.solve(J1, b, 1e-11);
    Eigen::MatrixXd dense;
    J1.to_dense(dense);
    const Eigen::VectorXd exact = dense.partialPivLu().solve(b);
    std::printf("shared substitutions (%s factors): %d GMRES iterations, |x - exact| / |exact| = "
                "%.1e\n",
                single ? "single" : "double", solver.last_iterations(),
                (x - exact).norm() / exact.norm());
    EXPECT_EQ(solver.factorizations(), 1) << single;
    // Rank k: k + 1 iterations in exact arithmetic, one more for the float factors' error (a
    // substitution missing one rank's tiles took 15 and 29 here).
    EXPECT_LE(solver.last_iterations(), k + 2) << single;
    EXPECT_LT(relative_residual(dense, x, b), 1e-11) << single;
    EXPECT_LE((x - exact).norm(), 1e-10 * exact.norm()) << single;
  }
}

TEST(ReusedLuSolver, SingleFactorsMeetTheSameTolerances) {
  const int m = 120, n = 180;
  const Eigen::MatrixXd S = -test_matrix(m, 5);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -2.0, 1.0);
  const CondensedNewtonMatrix J0 = condensed(S, n, 6, 1.0), J1 = condensed(S, n, 7, 3.0);
  ReusedLuSolver single, twice;
  single.set_single_precision_factors(true);
  for (const auto* J : {&J0, &J1}) {
    Eigen::MatrixXd dense;
    J->to_dense(dense);
    const Eigen::VectorXd exact = dense.partialPivLu().solve(b);
    const Eigen::VectorXd xs = single.solve(*J, b, 1e-11), xd = twice.solve(*J, b, 1e-11);
    std::printf("single factors: %d GMRES iterations (double %d), residual %.1e\n",
                single.last_iterations(), twice.last_iterations(), relative_residual(dense, xs, b));
    EXPECT_LT(relative_residual(dense, xs, b), 1e-11);
    EXPECT_LE((xs - exact).norm(), 1e-10 * exact.norm());
    // A fresh factorisation in float is not a solution by itself: GMRES refines it.
    if (J == &J0) {
      EXPECT_GT(single.last_iterations(), 0);
    }
  }
  EXPECT_EQ(single.factorizations(), 1);
  // reset() frees the float factors (their arrays go, not only a flag): the next solve
  // factorises again and meets the same tolerance.
  single.reset();
  {
    Eigen::MatrixXd dense;
    J1.to_dense(dense);
    const Eigen::VectorXd x1 = single.solve(J1, b, 1e-11);
    EXPECT_EQ(single.factorizations(), 2);
    EXPECT_LT(relative_residual(dense, x1, b), 1e-11);
  }
  // Beyond what float factors can precondition (condition number ~1e12): double takes over.
  Eigen::MatrixXd hard = test_matrix(60, 11);
  hard.row(3) = hard.row(4) + 1e-12 * hard.row(3);
  const Eigen::VectorXd c = Eigen::VectorXd::Ones(60);
  ReusedLuSolver fallback;
  fallback.set_single_precision_factors(true);
  const Eigen::VectorXd x = fallback.solve(hard, c, 1e-11);
  const Eigen::VectorXd exact = hard.partialPivLu().solve(c);
  std::printf("ill-conditioned: %d factorisations, |x - exact| / |exact| = %.1e\n",
              fallback.factorizations(), (x - exact).norm() / exact.norm());
  EXPECT_EQ(fallback.factorizations(), 2);
  EXPECT_LE((x - exact).norm(), 1e-3 * exact.norm());
}

// Fresh float factors of a matrix whose conditioning floor (κ = 1e6, b along the smallest
// singular direction: ‖J‖‖x‖/‖b‖ = κ) lies above the tight acceptance 1e-11: refinement
// stalls near 1e-10, which double factors would not beat either. With a loose forcing term
// the stalled solution is taken; before, the float factors were thrown away for double ones
// (twice their memory: the 1M-DOF pile's peak).
TEST(ReusedLuSolver, StalledRefinementMeetsTheForcingTermOnFloatFactors) {
  const int n = 150;
  std::srand(21);
  const Eigen::MatrixXd U =
      Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(n, n)).householderQ();
  const Eigen::MatrixXd V =
      Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(n, n)).householderQ();
  Eigen::VectorXd sigma(n);
  for (int i = 0; i < n; ++i)
    sigma(i) = std::pow(10.0, -6.0 * i / (n - 1));
  const Eigen::MatrixXd J = U * sigma.asDiagonal() * V.transpose();
  const Eigen::VectorXd b = U.col(n - 1) + 1e-3 * U.col(0);
  const Eigen::VectorXd exact = V * (U.transpose() * b).cwiseQuotient(sigma);
  ReusedLuSolver single;
  single.set_single_precision_factors(true);
  const double accept = 1e-6;
  const Eigen::VectorXd x = single.solve(J, b, accept);
  std::printf("floor above 1e-11: %d factorisation(s), %d GMRES iterations, residual %.1e, "
              "|x - exact| / |exact| = %.1e\n",
              single.factorizations(), single.last_iterations(), relative_residual(J, x, b),
              (x - exact).norm() / exact.norm());
  EXPECT_EQ(single.factorizations(), 1);
  EXPECT_LE(relative_residual(J, x, b), accept);
  EXPECT_GT(relative_residual(J, x, b), 1e-11); // the case: the tight acceptance is out of reach
  EXPECT_LE((x - exact).norm(), 1e-8 * exact.norm());
}

// A matrix drifting from its factors (6 more rows changed before each solve, as pairs change
// branch along a debonding front): from renew_from_rows on, the factors are renewed once the
// solves on them have taken more than refactor_after × n GMRES iterations, although GMRES
// still converges on them; below, they are kept. Every solution meets the acceptance.
TEST(ReusedLuSolver, RenewsLargeFactorsAfterTheirIterationBudget) {
  for (const int n : {static_cast<int>(ReusedLuSolver::renew_from_rows),
                      static_cast<int>(ReusedLuSolver::renew_from_rows) - 1}) {
    ReusedLuSolver solver;
    Eigen::MatrixXd J = test_matrix(n, 3);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, -2.0);
    solver.solve(J, b);
    int spent = 0, renewals = 0;
    for (int j = 0; j < 15; ++j) {
      for (int i = 0; i < 6; ++i) {               // a new row, as large as the diagonal everywhere
        const int r = (7 * (6 * j + i) + 11) % n; // 7: coprime with both n
        J.row(r) = n * Eigen::RowVectorXd::Random(n);
        J(r, r) += 2.0 * n;
      }
      const int before = solver.factorizations();
      const Eigen::VectorXd x = solver.solve(J, b);
      EXPECT_LT(relative_residual(J, x, b), 1e-11) << "n " << n << ", solve " << j;
      if (solver.factorizations() > before) {
        ++renewals;
        // Renewed only past the budget, not because GMRES failed on the old factors.
        EXPECT_GT(spent, ReusedLuSolver::refactor_after * n) << "n " << n << ", solve " << j;
        spent = solver.last_iterations();
      } else {
        spent += solver.last_iterations();
      }
    }
    std::printf("n = %d: %d renewal(s), %d GMRES iterations on the last factors\n", n, renewals,
                spent);
    if (n >= ReusedLuSolver::renew_from_rows) {
      EXPECT_EQ(renewals, 1);
    } else { // kept, although they took more than the budget
      EXPECT_EQ(renewals, 0);
      EXPECT_GT(spent, ReusedLuSolver::refactor_after * n);
    }
  }
}

} // namespace
} // namespace bipot
