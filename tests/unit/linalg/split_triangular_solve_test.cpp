// SplitTriangularSolve: the substitutions on tiles shared by the ranks (1 or 2 MPI ranks)
// give the serial Eigen LU solve, to 1e-12 relative with double factors and to float
// round-off with single ones, for sizes not divisible by the tile or the rank count; the
// result is the same bits on every rank.
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/split_triangular_solve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace bipot {
namespace {

// A deterministic nonsymmetric matrix (the same on every rank) whose LU pivots: the diagonal
// is not dominant, so the permutation matters.
Eigen::MatrixXd test_matrix(Index n) {
  Eigen::MatrixXd A(n, n);
  for (Index j = 0; j < n; ++j)
    for (Index i = 0; i < n; ++i)
      A(i, j) = std::sin(0.7 * static_cast<double>(i) + 0.45 * static_cast<double>(j * j % 97)) +
                (i == (j + 3) % n ? 4.0 : 0.0);
  return A;
}

template <class Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, 1>
split_solve(const Eigen::PartialPivLU<Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>>& lu,
            const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& b, Index block) {
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> x = lu.permutationP() * b;
  SplitTriangularSolve<Scalar>(lu.matrixLU(), block).solve_in_place(x);
  return x;
}

template <class Vector> void expect_same_on_every_rank(const Vector& x) {
  for (Index i = 0; i < x.size(); i += 7) {
    const double xi = static_cast<double>(x(i));
    EXPECT_EQ(max_all(xi), min_all(xi)) << "entry " << i;
  }
}

TEST(SplitTriangularSolve, DoubleFactorsGiveTheSerialSolve) {
  const Index n = 301; // 64-column tiles: 4 full and one of 45; odd, so not divisible by 2
  const Eigen::MatrixXd A = test_matrix(n);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 3.0).array().cos();
  const Eigen::VectorXd serial = lu.solve(b);
  ASSERT_LT((A * serial - b).norm(), 1e-10 * b.norm()); // a sound reference
  for (const Index block : {1, 64, 100, 512}) {
    const Eigen::VectorXd x = split_solve(lu, b, block);
    std::printf("double, block %ld, rank %d of %d: |x - serial| / |serial| = %.1e\n",
                static_cast<long>(block), mpi_rank(), mpi_size(),
                (x - serial).norm() / serial.norm());
    EXPECT_LE((x - serial).norm(), 1e-12 * serial.norm()) << "block " << block;
    expect_same_on_every_rank(x);
  }
}

TEST(SplitTriangularSolve, SingleFactorsGiveTheSerialSolveToFloatRoundOff) {
  const Index n = 203;
  const Eigen::MatrixXf A = test_matrix(n).cast<float>();
  const Eigen::PartialPivLU<Eigen::MatrixXf> lu(A);
  const Eigen::VectorXf b = Eigen::VectorXf::LinSpaced(n, 2.0f, -1.0f);
  const Eigen::VectorXf serial = lu.solve(b);
  for (const Index block : {32, 64}) {
    const Eigen::VectorXf x = split_solve(lu, b, block);
    std::printf("single, block %ld, rank %d of %d: |x - serial| / |serial| = %.1e\n",
                static_cast<long>(block), mpi_rank(), mpi_size(),
                static_cast<double>((x - serial).norm() / serial.norm()));
    // The same substitutions with the sums in another order: float round-off (6e-8) grown by
    // the conditioning of the factors (~1e2 here).
    EXPECT_LE((x - serial).norm(), 1e-5f * serial.norm()) << "block " << block;
    expect_same_on_every_rank(x);
  }
}

} // namespace
} // namespace bipot
