// SplitDenseProduct: the ranks' shares of S x add up to the serial Eigen product (to
// round-off, 1e-12 relative) for symmetric S (lower triangle only) and general S, sizes not
// divisible by the rank count; each share is needed (dropping one leaves an O(1) error); the
// shares read balanced numbers of entries; and the collective product (1 or 2 MPI ranks) is the
// serial one on every rank, bit for bit the same on all ranks.
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/condensed_newton_matrix.hpp"
#include "fem/linalg/split_dense_product.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace bipot {
namespace {

// A deterministic dense matrix (the same on every rank): symmetric with its strict upper
// triangle overwritten by NaN (a product that reads it fails), or general.
Eigen::MatrixXd test_matrix(Index m, bool symmetric) {
  Eigen::MatrixXd S(m, m);
  for (Index j = 0; j < m; ++j)
    for (Index i = 0; i < m; ++i)
      S(i, j) = std::sin(0.37 * static_cast<double>(i + 1) + 1.3 * static_cast<double>(j)) +
                (i == j ? 2.0 : 0.0);
  if (!symmetric) return S;
  Eigen::MatrixXd lower = S.triangularView<Eigen::Lower>();
  for (Index j = 0; j < m; ++j)
    for (Index i = 0; i < j; ++i)
      lower(i, j) = std::numeric_limits<double>::quiet_NaN();
  return lower;
}

Eigen::VectorXd serial_product(const Eigen::MatrixXd& S, bool symmetric, const Eigen::VectorXd& x) {
  if (symmetric) return S.selfadjointView<Eigen::Lower>() * x;
  return S * x;
}

Eigen::VectorXd test_vector(Index m) {
  return Eigen::VectorXd::LinSpaced(m, -1.0, 2.0).array().cos();
}

TEST(SplitDenseProduct, SharesAddUpToTheSerialProductAndEachIsNeeded) {
  for (const bool symmetric : {true, false})
    for (const Index m : {1, 5, 97, 301}) // 301: several 32-column panels, odd
      for (const int ranks : {1, 2, 3, 4}) {
        const Eigen::MatrixXd S = test_matrix(m, symmetric);
        const Eigen::VectorXd x = test_vector(m), reference = serial_product(S, symmetric, x);
        Eigen::VectorXd sum = Eigen::VectorXd::Zero(m);
        std::vector<Eigen::VectorXd> shares;
        for (int r = 0; r < ranks; ++r) {
          const SplitDenseProduct share(S, symmetric, r, ranks);
          shares.push_back(Eigen::VectorXd::Zero(m));
          share.add_share(shares.back(), x, 1.0);
          sum += shares.back();
        }
        SCOPED_TRACE("symmetric " + std::to_string(symmetric) + ", m " + std::to_string(m) +
                     ", ranks " + std::to_string(ranks));
        EXPECT_LE((sum - reference).norm(), 1e-12 * reference.norm());
        // Without any one non-empty share the product is off by the share itself, O(1).
        for (int r = 0; r < ranks; ++r) {
          if (shares[static_cast<std::size_t>(r)].norm() == 0.0) continue; // an empty range
          EXPECT_GT((sum - shares[static_cast<std::size_t>(r)] - reference).norm(),
                    1e-3 * reference.norm());
        }
      }
}

TEST(SplitDenseProduct, SharesReadBalancedNumbersOfEntries) {
  const Index m = 1001;
  for (const int ranks : {2, 3, 4}) {
    const std::vector<Index> sym = SplitDenseProduct::boundaries(m, true, ranks);
    const std::vector<Index> gen = SplitDenseProduct::boundaries(m, false, ranks);
    ASSERT_EQ(sym.size(), static_cast<std::size_t>(ranks) + 1);
    EXPECT_EQ(sym.front(), 0);
    EXPECT_EQ(sym.back(), m);
    EXPECT_EQ(gen.front(), 0);
    EXPECT_EQ(gen.back(), m);
    const double total = 0.5 * m * (m + 1.0);
    for (int r = 0; r < ranks; ++r) {
      // Entries of the lower triangle in columns [b_r, b_r+1): within one column (m) of the
      // equal share; rows of a general S within one row of m / ranks.
      const auto area = [&](Index c) { return c * m - 0.5 * c * (c - 1.0); };
      EXPECT_NEAR(area(sym[r + 1]) - area(sym[r]), total / ranks, m);
      EXPECT_NEAR(static_cast<double>(gen[r + 1] - gen[r]), static_cast<double>(m) / ranks, 1.0);
    }
  }
}

// The collective product over the MPI ranks of the test (1 or 2), and J x of the condensed
// Newton matrix that uses it, against the serial products.
TEST(SplitDenseProduct, CollectiveProductIsTheSerialOneOnEveryRank) {
  for (const bool symmetric : {true, false}) {
    const Index m = 257;
    const Eigen::MatrixXd S = test_matrix(m, symmetric);
    const Eigen::VectorXd x = test_vector(m), reference = serial_product(S, symmetric, x);
    const SplitDenseProduct split(S, symmetric);
    EXPECT_EQ(split.ranks(), mpi_size());
    const Eigen::VectorXd y = split.product(x);
    std::printf("symmetric %d, rank %d of %d: |Sx - serial| / |serial| = %.1e\n", symmetric,
                mpi_rank(), mpi_size(), (y - reference).norm() / reference.norm());
    EXPECT_LE((y - reference).norm(), 1e-12 * reference.norm()) << "symmetric " << symmetric;
    // The same bits on every rank (the ranks branch on these numbers in step).
    for (Index i = 0; i < m; i += 16) {
      EXPECT_EQ(max_all(y(i)), min_all(y(i))) << "entry " << i;
    }

    // J = [−S 0; 0 0] + P with a few sparse entries, n = m + 3 (a bordered Newton matrix).
    const Index n = m + 3;
    CondensedNewtonMatrix J(S, n, symmetric);
    J.set_sparse_part({{0, 0, 4.0}, {m + 2, 1, -1.5}, {5, m + 1, 2.5}, {m, m, 1.0}});
    Eigen::MatrixXd dense;
    J.to_dense(dense);
    const Eigen::VectorXd z = test_vector(n), Jz = J * z, dense_Jz = dense * z;
    EXPECT_LE((Jz - dense_Jz).norm(), 1e-12 * dense_Jz.norm()) << "symmetric " << symmetric;
    EXPECT_LE((J.dense_product(z.head(m)) - serial_product(S, symmetric, z.head(m))).norm(),
              1e-12 * dense_Jz.norm());
  }
}

} // namespace
} // namespace bipot
