#include "chain_problem.hpp"
#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/detail/mumps_diagnosis.hpp"
#include "fem/linalg/schur_complement_solver.hpp"

#include <unistd.h>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace bipot {
namespace {

using test::Chain;

// For the chain -u'' = 1 (element springs 1/h), eliminating every DOF between two kept DOFs
// at x_i < x_j leaves one spring of stiffness 1/(x_j - x_i) (springs in series), and the
// first and last kept DOFs are tied to the fixed ends by 1/x_1 and 1/(1 - x_m). So S is the
// tridiagonal stiffness of that coarse chain, exactly. The one-way tie adds k to row tie_a
// at columns (tie_a, tie_b) when both are kept.
Eigen::MatrixXd coarse_chain(const Chain& c, const std::vector<Index>& kept) {
  const Index m = static_cast<Index>(kept.size());
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(m, m);
  auto x = [&](Index dof) { return static_cast<double>(dof + 1) * c.h(); };
  for (Index i = 0; i < m; ++i) {
    const double left = i == 0 ? x(kept[0]) : x(kept[i]) - x(kept[i - 1]);
    const double right = i == m - 1 ? 1.0 - x(kept[i]) : x(kept[i + 1]) - x(kept[i]);
    S(i, i) = 1.0 / left + 1.0 / right;
    if (i + 1 < m) S(i, i + 1) = S(i + 1, i) = -1.0 / right;
  }
  return S;
}

TEST(SchurComplementSolver, IsTheCoarseChainAndExpandsToTheExactSolution) {
  Chain chain;
  chain.one_way_tie = true; // unsymmetric, as friction makes the contact tangent
  const auto dist = chain.distribution();
  SparseMatrix A(dist, chain.pattern(dist));
  chain.assemble(A);
  // Kept DOFs on both ranks' rows (2 ranks split 99 rows at 49/50), given out of order.
  const std::vector<Index> kept = {50, chain.tie_a, chain.tie_b(), 20};
  SchurComplementSolver solver;
  solver.factorize(A, kept);
  const std::vector<Index> sorted = {chain.tie_a, 20, 50, chain.tie_b()};
  ASSERT_EQ(solver.schur_dofs(), sorted);

  Eigen::MatrixXd expected = coarse_chain(chain, sorted);
  expected(0, 0) += chain.tie_stiffness; // row tie_a: k (u_a - u_b)
  expected(0, 3) -= chain.tie_stiffness;
  // Entries are O(1/h) = 100; MUMPS' backward error is near machine precision.
  EXPECT_LT((solver.schur() - expected).norm() / expected.norm(), 1e-12)
      << "S =\n"
      << solver.schur() << "\nexpected\n"
      << expected;

  DistributedVector b(dist), x(dist);
  chain.assemble_rhs(b);
  // The one-way tie makes S unsymmetric by the tie stiffness: not taken for symmetric.
  EXPECT_FALSE(solver.symmetric()) << solver.asymmetry();
  const Eigen::VectorXd c = solver.reduce(b);
  ASSERT_EQ(c.size(), 4);
  const Eigen::VectorXd x_kept = solver.schur().partialPivLu().solve(c);
  for (Index i = 0; i < 4; ++i) // the exact solution is nodally exact for linear elements
    EXPECT_NEAR(x_kept(i), chain.exact(sorted[i]), 1e-13) << "kept DOF " << sorted[i];
  solver.expand(x_kept, x);
  EXPECT_LT(test::relative_error(x, [&](Index d) { return chain.exact(d); }), 1e-12);

  // Refactorising new values with the same kept set reuses the analysis and stays exact.
  chain.assemble(A, 2.0);
  solver.factorize(A, kept);
  EXPECT_LT((solver.schur() - 2.0 * expected).norm() / expected.norm(), 1e-12);
  const Eigen::VectorXd x2 = solver.schur().partialPivLu().solve(solver.reduce(b));
  solver.expand(x2, x);
  EXPECT_LT(test::relative_error(x, [&](Index d) { return 0.5 * chain.exact(d); }), 1e-12);
}

// A symmetric A (a two-way tie) gives S symmetric to round-off, which the Newton matrix then
// reads by its lower triangle.
TEST(SchurComplementSolver, SymmetricMatrixGivesASymmetricComplement) {
  Chain chain;
  chain.one_way_tie = false;
  const auto dist = chain.distribution();
  SparseMatrix A(dist, chain.pattern(dist));
  chain.assemble(A);
  SchurComplementSolver solver;
  solver.factorize(A, {50, chain.tie_a, chain.tie_b(), 20});
  std::printf("asymmetry of S: %.1e\n", solver.asymmetry());
  EXPECT_LE(solver.asymmetry(), SchurComplementSolver::symmetric_within);
  EXPECT_TRUE(solver.symmetric());
  const Eigen::MatrixXd& S = solver.schur();
  EXPECT_LE((S - S.transpose()).norm(), 1e-13 * S.norm());

  // The same with an LDLᵀ factorisation from the lower triangle: S (all of it, mirrored)
  // and the expanded solution as exact as with the LU.
  SchurComplementSolver ldlt;
  ldlt.factorize(A, {50, chain.tie_a, chain.tie_b(), 20}, true);
  std::printf("LDL^T: |S - S_LU| / |S_LU| = %.1e\n", (ldlt.schur() - S).norm() / S.norm());
  EXPECT_LE((ldlt.schur() - S).norm(), 1e-12 * S.norm());
  EXPECT_EQ((ldlt.schur() - ldlt.schur().transpose()).norm(), 0.0);
  DistributedVector b(dist), x(dist);
  chain.assemble_rhs(b);
  const Eigen::VectorXd x_kept = ldlt.schur().partialPivLu().solve(ldlt.reduce(b));
  ldlt.expand(x_kept, x);
  DistributedVector x_lu(dist);
  solver.expand(solver.schur().partialPivLu().solve(solver.reduce(b)), x_lu);
  x_lu.axpy(-1.0, x);
  std::printf("LDL^T: |x - x_LU| / |x_LU| = %.1e\n", x_lu.norm2() / x.norm2());
  EXPECT_LE(x_lu.norm2(), 1e-12 * x.norm2());
}

TEST(SchurComplementSolver, FailsOnEveryRankWhenTheRestIsSingular) {
  // Zero stiffness everywhere: A_BB = 0. (MUMPS reports no error for it by itself in Schur
  // mode; the factorisation counts null pivots.)
  Chain chain;
  const auto dist = chain.distribution();
  SparseMatrix A(dist, chain.pattern(dist));
  chain.assemble(A, 0.0);
  SchurComplementSolver solver;
  std::string message;
  try {
    solver.factorize(A, {chain.tie_a});
  } catch (const SolverError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("numerically singular matrix outside the Schur variables"),
            std::string::npos)
      << message;
}

// Out of core: MUMPS keeps the factors of A_BB in files, reads them back at reduce() and
// expand(), and removes them with the solver. S and the expanded solution are those of the
// in-memory factors (the same arithmetic; 1e-14 allows for a different summation order).
TEST(SchurComplementSolver, OutOfCoreFactorsGiveTheSameSolutionAndAreRemoved) {
  namespace fs = std::filesystem;
  Chain chain;
  chain.one_way_tie = true;
  const auto dist = chain.distribution();
  SparseMatrix A(dist, chain.pattern(dist));
  chain.assemble(A);
  const std::vector<Index> kept = {50, chain.tie_a, chain.tie_b(), 20};
  DistributedVector b(dist), x_memory(dist), x_disk(dist);
  chain.assemble_rhs(b);
  SchurComplementSolver memory;
  memory.factorize(A, kept);
  memory.expand(memory.schur().partialPivLu().solve(memory.reduce(b)), x_memory);

  // Each rank's own directory (MUMPS writes a rank's part of the factors where that rank
  // says).
  const fs::path dir = fs::temp_directory_path() / ("bipot_ooc_test_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  auto files = [&] { return std::distance(fs::directory_iterator(dir), fs::directory_iterator()); };
  {
    SchurComplementSolver disk;
    disk.set_factor_directory(dir.string());
    disk.factorize(A, kept);
    // At least one rank holds factor files (on 2 ranks MUMPS may give this small matrix to one).
    EXPECT_GT(sum_all(static_cast<double>(files())), 0.0) << "no factor file in " << dir;
    EXPECT_LE((disk.schur() - memory.schur()).norm(), 1e-14 * memory.schur().norm());
    disk.expand(disk.schur().partialPivLu().solve(disk.reduce(b)), x_disk);
    EXPECT_LT(test::relative_error(x_disk, [&](Index d) { return chain.exact(d); }), 1e-12);
    x_disk.axpy(-1.0, x_memory);
    EXPECT_LE(x_disk.norm2(), 1e-14 * x_memory.norm2());
  }
  EXPECT_EQ(files(), 0) << "factor files left in " << dir;
  fs::remove_all(dir);
}

// What a MUMPS failure tells the user: the codes by name, and for a failed allocation what
// to change (factors to files), unless they were in files already.
TEST(MumpsDiagnosis, NamesTheCodesAndTellsWhatToChange) {
  const std::string memory = detail::mumps_error(-13, 123456, false);
  EXPECT_NE(memory.find("memory allocation failed (MUMPS INFOG(1) = -13, INFOG(2) = 123456)"),
            std::string::npos)
      << memory;
  EXPECT_NE(memory.find("out_of_core: true"), std::string::npos) << memory;
  const std::string on_disk = detail::mumps_error(-13, 7, true);
  EXPECT_EQ(on_disk.find("out_of_core: true"), std::string::npos) << on_disk;
  EXPECT_NE(on_disk.find("more memory"), std::string::npos) << on_disk;
  EXPECT_EQ(detail::mumps_error(-10, 3, false),
            "numerically singular matrix (MUMPS INFOG(1) = -10, INFOG(2) = 3)");
  EXPECT_EQ(detail::mumps_error(-40, 0, false), "MUMPS INFOG(1) = -40, INFOG(2) = 0");
}

} // namespace
} // namespace bipot
