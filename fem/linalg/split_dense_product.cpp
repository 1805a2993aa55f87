#include "fem/linalg/split_dense_product.hpp"

#include "fem/linalg/communicator.hpp"

#include <algorithm>

namespace bipot {

namespace {
// Columns of the lower triangle handled together: the panel below the diagonal block is read
// from memory by the first product and, while it is still in cache (32 columns × 4600 rows is
// 1.2 MB, within the 2 MB L2), again by the transposed one, so S is streamed once.
constexpr Index panel_columns = 32;
} // namespace

SplitDenseProduct::SplitDenseProduct(const Eigen::MatrixXd& S, bool symmetric)
    : SplitDenseProduct(S, symmetric, mpi_rank(), mpi_size()) {}

SplitDenseProduct::SplitDenseProduct(const Eigen::MatrixXd& S, bool symmetric, int rank, int ranks)
    : S_(&S), symmetric_(symmetric), ranks_(ranks) {
  const std::vector<Index> b = boundaries(S.rows(), symmetric, ranks);
  begin_ = b[static_cast<std::size_t>(rank)];
  end_ = b[static_cast<std::size_t>(rank) + 1];
}

std::vector<Index> SplitDenseProduct::boundaries(Index m, bool symmetric, int ranks) {
  std::vector<Index> b(static_cast<std::size_t>(ranks) + 1, m);
  b[0] = 0;
  if (!symmetric) {
    for (int r = 1; r < ranks; ++r)
      b[static_cast<std::size_t>(r)] = m * r / ranks;
    return b;
  }
  // Column j of the lower triangle holds m − j entries; rank r's range ends where the entries
  // up to it first reach r + 1 shares of m (m + 1) / 2.
  const double total = 0.5 * static_cast<double>(m) * static_cast<double>(m + 1);
  double area = 0;
  int r = 1;
  for (Index j = 0; j < m && r < ranks; ++j) {
    area += static_cast<double>(m - j);
    while (r < ranks && area >= total * r / ranks)
      b[static_cast<std::size_t>(r++)] = j + 1;
  }
  return b;
}

void SplitDenseProduct::add_share(Eigen::Ref<Eigen::VectorXd> y,
                                  const Eigen::Ref<const Eigen::VectorXd>& x, double alpha) const {
  const Eigen::MatrixXd& S = *S_;
  const Index m = S.rows();
  if (!symmetric_) {
    y.segment(begin_, end_ - begin_).noalias() += alpha * (S.middleRows(begin_, end_ - begin_) * x);
    return;
  }
  for (Index j0 = begin_; j0 < end_; j0 += panel_columns) {
    const Index w = std::min(panel_columns, end_ - j0), below = m - j0 - w;
    const auto xj = x.segment(j0, w);
    y.segment(j0, w).noalias() +=
        alpha * (S.block(j0, j0, w, w).selfadjointView<Eigen::Lower>() * xj);
    if (below == 0) continue;
    const auto panel = S.block(j0 + w, j0, below, w);
    y.segment(j0 + w, below).noalias() += alpha * (panel * xj);
    y.segment(j0, w).noalias() += alpha * (panel.transpose() * x.tail(below));
  }
}

Eigen::VectorXd SplitDenseProduct::product(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(S_->rows());
  add_share(y, x, 1.0);
  if (ranks_ > 1) sum_all(y.data(), y.size());
  return y;
}

} // namespace bipot
