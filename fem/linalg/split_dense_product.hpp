#pragma once
/// Products with a dense matrix that every rank holds, the work shared by the ranks.

#include "fem/core/types.hpp"

#include <Eigen/Dense>

#include <vector>

namespace bipot {

/// y = S x for a dense m × m matrix S held whole on every rank (the Schur complement of
/// generalized_newton), each rank computing a share and one sum over the ranks (m doubles)
/// giving S x on every rank. Streaming S is what a product costs (m² doubles, or m²/2 for a
/// symmetric S read from its lower triangle), so the shares are balanced by the entries read:
/// - symmetric S: consecutive column ranges of the lower triangle with equal areas (the
///   first rank's columns are the longest, so its range is the narrowest); each column j
///   contributes S(j:m, j) x_j to rows j..m and S(j+1:m, j)ᵀ x(j+1:m) to row j;
/// - otherwise: consecutive row ranges with equal numbers of rows.
/// A rank's share reads only its own part of S.
class SplitDenseProduct {
public:
  /// The share of the calling MPI rank. `S` must outlive this object; `symmetric`: only the
  /// lower triangle of S is read.
  SplitDenseProduct(const Eigen::MatrixXd& S, bool symmetric);
  /// The share of rank `rank` of `ranks` (tests).
  SplitDenseProduct(const Eigen::MatrixXd& S, bool symmetric, int rank, int ranks);

  /// S x on every rank (collective: every rank passes the same x).
  Eigen::VectorXd product(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  /// y += alpha × this rank's share of S x (no communication; y and x of length m).
  void add_share(Eigen::Ref<Eigen::VectorXd> y, const Eigen::Ref<const Eigen::VectorXd>& x,
                 double alpha) const;

  /// This rank's columns (symmetric S) or rows, [begin, end).
  Index begin() const { return begin_; }
  Index end() const { return end_; }
  int ranks() const { return ranks_; }

  /// Where the shares of `ranks` ranks start: ranks + 1 boundaries from 0 to m.
  static std::vector<Index> boundaries(Index m, bool symmetric, int ranks);

private:
  const Eigen::MatrixXd* S_;
  bool symmetric_;
  int ranks_;
  Index begin_ = 0, end_ = 0;
};

} // namespace bipot
