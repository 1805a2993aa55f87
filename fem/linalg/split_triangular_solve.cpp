#include "fem/linalg/split_triangular_solve.hpp"

#include "fem/linalg/communicator.hpp"

#include <algorithm>

namespace bipot {

template <class Scalar>
SplitTriangularSolve<Scalar>::SplitTriangularSolve(const Matrix& lu, Index block)
    : lu_(&lu), block_(std::max<Index>(block, 1)), rank_(mpi_rank()), ranks_(mpi_size()) {}

template <class Scalar> void SplitTriangularSolve<Scalar>::solve_in_place(Vector& x) const {
  const Matrix& A = *lu_;
  const Index n = A.rows(), blocks = (n + block_ - 1) / block_;
  const auto width = [&](Index k) { return std::min(block_, n - k * block_); };
  // The first of this rank's tiles in block row k at or after block column `from`.
  const auto first_tile = [&](Index k, Index from) {
    const Index shift = ((rank_ - (k + from)) % ranks_ + ranks_) % ranks_;
    return from + shift;
  };
  Vector t;
  const auto block_row = [&](Index k, Index from, Index to) {
    const Index r0 = k * block_, h = width(k);
    t.setZero(h);
    for (Index j = first_tile(k, from); j < to; j += ranks_)
      t.noalias() += A.block(r0, j * block_, h, width(j)) * x.segment(j * block_, width(j));
    if (ranks_ > 1) sum_all(t.data(), h);
    x.segment(r0, h) -= t;
  };
  for (Index k = 0; k < blocks; ++k) { // L y = b, L unit lower
    block_row(k, 0, k);
    const Index r0 = k * block_, h = width(k);
    A.block(r0, r0, h, h)
        .template triangularView<Eigen::UnitLower>()
        .solveInPlace(x.segment(r0, h));
  }
  for (Index k = blocks - 1; k >= 0; --k) { // U x = y
    block_row(k, k + 1, blocks);
    const Index r0 = k * block_, h = width(k);
    A.block(r0, r0, h, h).template triangularView<Eigen::Upper>().solveInPlace(x.segment(r0, h));
  }
}

template class SplitTriangularSolve<float>;
template class SplitTriangularSolve<double>;

} // namespace bipot
