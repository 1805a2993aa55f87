#pragma once
/// The Newton matrix of a condensed system, kept as a dense block plus a sparse rest.

#include "fem/core/types.hpp"
#include "fem/linalg/split_dense_product.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <vector>

namespace bipot {

/// J = [−S 0; 0 0] + P (n × n): S the dense Schur complement of the linear bulk on the
/// interface DOFs (the top-left |S| × |S| block, fixed over a stage, not copied), P sparse (the
/// interface terms, a few entries per pair, and a bordering row and column if any). Each
/// Newton iteration changes P only, so it is rebuilt from triplets and J is applied as
/// −S x + P x; the dense J (n² doubles, 170 MB at n = 4600) is formed only when it is
/// factorised. The products with S are shared by the MPI ranks (SplitDenseProduct): every
/// rank must make the same products in the same order (the ranks run the same iteration).
class CondensedNewtonMatrix {
public:
  /// `S` must outlive this matrix; n ≥ S.rows(). `symmetric_S`: S is symmetric (to
  /// round-off), and only its lower triangle is read (products and dense form): each product
  /// streams half of S (shared by the ranks).
  CondensedNewtonMatrix(const Eigen::MatrixXd& S, Index n, bool symmetric_S = false);

  Index rows() const { return n_; }
  Index cols() const { return n_; }
  const Eigen::MatrixXd& dense_block() const { return *S_; }
  const Eigen::SparseMatrix<double>& sparse_part() const { return P_; }

  /// P from (row, column, value) entries, duplicates summed.
  void set_sparse_part(const std::vector<Eigen::Triplet<double>>& entries);

  /// dst += alpha J x (collective).
  template <class Dst, class X> void add_product(Dst& dst, const X& x, double alpha) const {
    const Index m = S_->rows();
    dst.head(m).noalias() -= alpha * dense_product(x.head(m));
    dst.noalias() += alpha * (P_ * x);
  }
  /// S x_S, x_S of length |S| (collective): the products of the Newton residual.
  Eigen::VectorXd dense_product(const Eigen::Ref<const Eigen::VectorXd>& x_S) const {
    return split_.product(x_S);
  }
  /// J x (collective).
  Eigen::VectorXd operator*(const Eigen::VectorXd& x) const {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(n_);
    add_product(y, x, 1.0);
    return y;
  }
  /// The dense J, in `out` (resized), in double or single precision.
  template <class Scalar>
  void to_dense(Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& out) const;

private:
  const Eigen::MatrixXd* S_;
  Index n_;
  bool symmetric_;
  SplitDenseProduct split_;
  Eigen::SparseMatrix<double> P_;
};

} // namespace bipot
