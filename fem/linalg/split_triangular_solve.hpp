#pragma once
/// The forward and back substitutions of dense LU factors, shared by the ranks.

#include "fem/core/types.hpp"

#include <Eigen/Dense>

namespace bipot {

/// x = U⁻¹ L⁻¹ b for in-place LU factors that every rank holds (L unit lower below the
/// diagonal, U on and above it, as Eigen's PartialPivLU stores them; the row permutation is
/// the caller's): the preconditioner of ReusedLuSolver, which otherwise streams all n² factors
/// on every rank at every GMRES iteration. The factors are cut into tiles of `block` × `block`;
/// tile (k, j) belongs to rank (k + j) mod ranks, so that each block row's tiles alternate
/// between the ranks. Block row k of a substitution (L(k, j < k) y_j forward,
/// U(k, j > k) x_j back) is summed by each rank over its own tiles, and one sum over the ranks
/// (`block` values) completes it; every rank then solves the diagonal tile itself (n × block
/// entries per solve are read by all ranks, against n² shared). A rank thus reads about
/// 1/ranks of the factors per solve, at the price of 2 n / block sums over the ranks.
/// With one rank this is the serial blocked substitution (the same sums in another order).
template <class Scalar> class SplitTriangularSolve {
public:
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  /// Columns per tile: 256 keeps a block row's sums over the ranks to ~36 per solve at
  /// n = 4600 while the replicated diagonal tiles are 6 % of the factors.
  static constexpr Index default_block = 256;

  /// The tiles of the calling MPI rank. `lu` must outlive this object.
  explicit SplitTriangularSolve(const Matrix& lu, Index block = default_block);

  /// b ← U⁻¹ L⁻¹ b on every rank (collective: every rank passes the same b).
  void solve_in_place(Vector& b) const;

private:
  const Matrix* lu_;
  Index block_;
  int rank_, ranks_;
};

extern template class SplitTriangularSolve<float>;
extern template class SplitTriangularSolve<double>;

} // namespace bipot
