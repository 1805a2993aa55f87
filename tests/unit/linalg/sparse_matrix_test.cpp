#include "chain_problem.hpp"
#include "fem/core/error.hpp"

#include <gtest/gtest.h>

namespace bipot {
namespace {

using test::Chain;

// The chain matrix has entries +-100 (1/h and the tie stiffness) and the test vectors are
// small integers, so every product below is an exact integer: comparisons are exact.

DistributedVector filled(const DofDistribution& d, const std::function<double(Index)>& f) {
  DistributedVector v(d);
  for (Index i = v.first_owned(); i < v.first_owned() + v.num_owned(); ++i)
    v.set_owned(i, f(i));
  return v;
}

TEST(SparseMatrix, ChainProductsMatchTheStencil) {
  const Chain chain;
  const auto dist = chain.distribution();
  SparseMatrix A(dist, chain.pattern(dist));
  chain.assemble(A);
  const Index n = chain.num_dofs(), a = chain.tie_a, b = chain.tie_b();
  const double k = 1.0 / chain.h(), kt = chain.tie_stiffness;
  EXPECT_EQ(A.num_global_rows(), n);
  EXPECT_EQ(A.num_global_entries(), 3 * n - 2 + 2); // tridiagonal + the two tie entries

  DistributedVector y(dist);
  A.multiply(filled(dist, [](Index) { return 1.0; }), y); // row sums
  for (Index i = y.first_owned(); i < y.first_owned() + y.num_owned(); ++i)
    EXPECT_EQ(y.get_owned(i), (i == 0 || i == n - 1) ? k : 0.0) << "row " << i;

  A.multiply(filled(dist, [](Index i) { return static_cast<double>(i); }), y);
  for (Index i = y.first_owned(); i < y.first_owned() + y.num_owned(); ++i) {
    double expected = i == 0 ? -k : (i == n - 1 ? n * k : 0.0);
    if (i == a) expected += kt * static_cast<double>(a - b);
    if (i == b) expected += kt * static_cast<double>(b - a);
    EXPECT_EQ(y.get_owned(i), expected) << "row " << i;
  }

  const auto diag = A.diagonal();
  for (Index i = diag.first_owned(); i < diag.first_owned() + diag.num_owned(); ++i)
    EXPECT_EQ(diag.get_owned(i), 2 * k + ((i == a || i == b) ? kt : 0.0));
}

TEST(SparseMatrix, RefillReusesThePatternAndReplacesValues) {
  const Chain chain;
  const auto dist = chain.distribution();
  SparseMatrix A(dist, chain.pattern(dist));
  chain.assemble(A);
  chain.assemble(A, 3.0); // same matrix object: set_zero() + new values
  const auto diag = A.diagonal();
  for (Index i = diag.first_owned(); i < diag.first_owned() + diag.num_owned(); ++i) {
    const bool tied = i == chain.tie_a || i == chain.tie_b();
    EXPECT_EQ(diag.get_owned(i), 3 * (2 / chain.h() + (tied ? chain.tie_stiffness : 0.0)));
  }
  EXPECT_EQ(A.num_global_entries(), 3 * chain.num_dofs());
}

TEST(SparseMatrix, SingleEntriesAddToTheDiagonal) {
  const Chain chain;
  const auto dist = chain.distribution();
  SparseMatrix A(dist, chain.pattern(dist));
  chain.assemble(A);
  A.set_zero();
  // Each rank adds 1 to the diagonal of its first owned row (always in the pattern).
  A.add(dist.first_owned_dof(), dist.first_owned_dof(), 1.0);
  A.finish_assembly();
  const auto diag = A.diagonal();
  for (Index i = diag.first_owned(); i < diag.first_owned() + diag.num_owned(); ++i)
    EXPECT_EQ(diag.get_owned(i), i == dist.first_owned_dof() ? 1.0 : 0.0);
}

TEST(SparseMatrix, EntriesOutsideThePatternThrow) {
  const Chain chain;
  const auto dist = chain.distribution();
  SparseMatrix A(dist, chain.pattern(dist));
  const Index n = chain.num_dofs();
  const Index row = dist.first_owned_dof();
  const Index far = (row + n / 2) % n; // never a neighbour of row, nor the tie partner
  ASSERT_GT(std::abs(far - row), 1);
  ASSERT_NE(row, chain.tie_a);
  const Index dofs[2] = {row, far};
  const double values[4] = {1, 1, 1, 1};
  EXPECT_THROW(A.add_dense(dofs, 2, values), Error);
  EXPECT_THROW(A.add(row, far, 1.0), Error);
  try {
    A.add(row, far, 1.0);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not in the sparsity pattern"), std::string::npos);
  }
  if (dist.size() > 1 && chain.assembles_tie(dist)) {
    // A ghost row: the tie row is known here only with columns {tie_a, tie_b}.
    EXPECT_THROW(A.add(chain.tie_a, chain.tie_a + 1, 1.0), Error);
    A.add(chain.tie_a, chain.tie_b(), 1.0);
  }
  // A row neither owned nor touched by this rank's pattern.
  if (dist.size() > 1) {
    const Index foreign = dist.rank() == 0 ? n - 1 : 0;
    EXPECT_THROW(A.add(foreign, foreign, 1.0), Error);
  }
  A.finish_assembly();
  EXPECT_THROW(A.add(row, row, 1.0), Error); // closed until set_zero()
}

TEST(SparseMatrix, InvalidPatternThrowsOnEveryRank) {
  const DofDistribution dist(10, 1);
  SparsityPattern p;
  if (dist.rank() == 0) p.add_cell({0, 10}); // DOF 10 does not exist
  EXPECT_THROW(SparseMatrix(dist, p), Error);
}

TEST(SparseMatrix, ProductNeedsFinishedAssembly) {
  const Chain chain;
  const auto dist = chain.distribution();
  SparseMatrix A(dist, chain.pattern(dist));
  DistributedVector x(dist), y(dist);
  EXPECT_THROW(A.multiply(x, y), Error);
}

} // namespace
} // namespace bipot
