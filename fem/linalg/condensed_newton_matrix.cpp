#include "fem/linalg/condensed_newton_matrix.hpp"

namespace bipot {

CondensedNewtonMatrix::CondensedNewtonMatrix(const Eigen::MatrixXd& S, Index n, bool symmetric_S)
    : S_(&S), n_(n), symmetric_(symmetric_S), split_(S, symmetric_S), P_(n, n) {}

void CondensedNewtonMatrix::set_sparse_part(const std::vector<Eigen::Triplet<double>>& entries) {
  P_.setFromTriplets(entries.begin(), entries.end());
}

template <class Scalar>
void CondensedNewtonMatrix::to_dense(
    Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& out) const {
  const Index m = S_->rows();
  out.resize(n_, n_);
  out.setZero();
  if (symmetric_) { // the lower triangle, mirrored (no temporary of S's size)
    for (Index j = 0; j < m; ++j)
      for (Index i = j; i < m; ++i)
        out(i, j) = out(j, i) = -static_cast<Scalar>((*S_)(i, j));
  } else {
    out.topLeftCorner(m, m) = -S_->template cast<Scalar>();
  }
  for (Index c = 0; c < P_.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(P_, c); it; ++it)
      out(it.row(), it.col()) += static_cast<Scalar>(it.value());
}

template void CondensedNewtonMatrix::to_dense(Eigen::MatrixXd&) const;
template void CondensedNewtonMatrix::to_dense(Eigen::MatrixXf&) const;

} // namespace bipot
