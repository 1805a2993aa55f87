#include "fem/linalg/sparse_matrix.hpp"

#include "fem/core/error.hpp"
#include "fem/linalg/detail/tpetra_types.hpp"

#include <Tpetra_Core.hpp>

#include <mpi.h>

#include <string>

namespace bipot {

using detail::GO;

namespace {

[[noreturn]] void throw_not_in_pattern(Index row, Index col) {
  throw Error("SparseMatrix: entry (" + std::to_string(row) + ", " + std::to_string(col) +
              ") is not in the sparsity pattern");
}

std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> displs(counts.size(), 0);
  for (std::size_t i = 1; i < counts.size(); ++i)
    displs[i] = displs[i - 1] + counts[i - 1];
  return displs;
}

} // namespace

SparseMatrix::Impl::Impl(const DofDistribution& d, const SparsityPattern& pattern)
    : dist(d), layout(d, pattern) {
  auto comm = Tpetra::getDefaultComm();
  const Index n_owned = dist.num_owned_dofs();
  row_map = Teuchos::rcp(new detail::Map(static_cast<Tpetra::global_size_t>(dist.num_global_dofs()),
                                         static_cast<std::size_t>(n_owned), GO(0), comm));
  const auto& remote = layout.remote_columns();
  if (remote.empty() && comm->getSize() == 1) {
    // The columns are the rows: the contiguous row map, which Tpetra stores without a list of
    // its indices (one whole-mesh array less per matrix). Only on one rank: the column map is
    // local, but Tpetra's constructor of a map from an index list is collective.
    col_map = row_map;
  } else {
    std::vector<GO> col_gids(static_cast<std::size_t>(n_owned));
    for (Index i = 0; i < n_owned; ++i)
      col_gids[i] = static_cast<GO>(dist.first_owned_dof() + i);
    col_gids.insert(col_gids.end(), remote.begin(), remote.end());
    col_map = Teuchos::rcp(new detail::Map(
        Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
        Teuchos::ArrayView<const GO>(col_gids.data(), col_gids.size()), GO(0), comm));
  }

  // Exact row sizes and local column indices: no global-index stage, no reallocation.
  const auto& sizes = layout.owned_row_sizes();
  graph = Teuchos::rcp(new detail::CrsGraph(
      row_map, col_map, Teuchos::ArrayView<const std::size_t>(sizes.data(), sizes.size()),
      Tpetra::StaticProfile));
  layout.visit_owned_rows([&](int row, const std::vector<int>& cols) {
    graph->insertLocalIndices(row, Teuchos::ArrayView<const int>(cols.data(), cols.size()));
  });
  graph->fillComplete(row_map, row_map);
  local_graph = graph->getLocalGraphHost();
  matrix = Teuchos::rcp(new detail::CrsMatrix(graph));
  ghost_values.assign(layout.ghost_cols().size(), 0.0);
}

SparseMatrix::SparseMatrix(const DofDistribution& dist, const SparsityPattern& pattern)
    : impl_(std::make_unique<Impl>(dist, pattern)) {
  set_zero();
}

SparseMatrix::~SparseMatrix() = default;
SparseMatrix::SparseMatrix(SparseMatrix&&) noexcept = default;
SparseMatrix& SparseMatrix::operator=(SparseMatrix&&) noexcept = default;

const DofDistribution& SparseMatrix::distribution() const {
  return impl_->dist;
}

Index SparseMatrix::num_global_rows() const {
  return impl_->dist.num_global_dofs();
}

Index SparseMatrix::num_global_entries() const {
  return static_cast<Index>(impl_->graph->getGlobalNumEntries());
}

void SparseMatrix::set_zero() {
  auto& m = *impl_->matrix;
  if (m.isFillComplete()) m.resumeFill();
  m.setAllToScalar(0.0);
  // A view of host memory (the Serial node); taken again at every assembly so that nothing
  // relies on Tpetra keeping the same storage across fillComplete() and resumeFill().
  impl_->values = m.getLocalValuesView().data();
  std::fill(impl_->ghost_values.begin(), impl_->ghost_values.end(), 0.0);
  impl_->assembling = true;
}

void SparseMatrix::add_block(const Index* rows, int n_rows, const Index* cols, int n_cols,
                             const double* values) {
  auto& im = *impl_;
  if (!im.assembling) throw Error("SparseMatrix: add after finish_assembly(); call set_zero()");
  const auto& layout = im.layout;
  const Index first = im.dist.first_owned_dof();
  const Index n_owned = im.dist.num_owned_dofs();
  for (int i = 0; i < n_rows; ++i) {
    const Index row = rows[i];
    if (row < 0) continue;
    const double* row_values = values + static_cast<std::size_t>(i) * n_cols;
    if (row >= first && row < first + n_owned) {
      // The row's local columns are ascending (the graph is fill-complete).
      const auto lr = static_cast<std::size_t>(row - first);
      const int* begin = im.local_graph.entries.data() + im.local_graph.row_map(lr);
      const int* end = im.local_graph.entries.data() + im.local_graph.row_map(lr + 1);
      double* row_entries = im.values + im.local_graph.row_map(lr);
      for (int j = 0; j < n_cols; ++j) {
        if (cols[j] < 0) continue;
        const int lc = layout.local_column(cols[j]);
        const int* at = std::lower_bound(begin, end, lc);
        if (lc < 0 || at == end || *at != lc) throw_not_in_pattern(row, cols[j]);
        row_entries[at - begin] += row_values[j];
      }
      continue;
    }
    const Index g = layout.ghost_index(row);
    if (g < 0) throw_not_in_pattern(row, n_cols > 0 ? cols[0] : -1);
    const auto begin = layout.ghost_cols().begin() + layout.ghost_offsets()[g];
    const auto end = layout.ghost_cols().begin() + layout.ghost_offsets()[g + 1];
    for (int j = 0; j < n_cols; ++j) {
      if (cols[j] < 0) continue;
      const auto it = std::lower_bound(begin, end, cols[j]);
      if (it == end || *it != cols[j]) throw_not_in_pattern(row, cols[j]);
      im.ghost_values[it - layout.ghost_cols().begin()] += row_values[j];
    }
  }
}

void SparseMatrix::add_dense(const Index* dofs, int n, const double* values_row_major) {
  add_block(dofs, n, dofs, n, values_row_major);
}

void SparseMatrix::add(Index row, Index col, double value) {
  if (row < 0 || col < 0) throw_not_in_pattern(row, col);
  add_block(&row, 1, &col, 1, &value);
}

void SparseMatrix::finish_assembly() {
  auto& im = *impl_;
  if (!im.assembling) throw Error("SparseMatrix: finish_assembly() called twice");
  const auto& layout = im.layout;
  const auto& recv_counts = layout.recv_counts();
  const auto& send_counts = layout.send_counts();
  if (im.dist.size() > 1) {
    const auto sdispl = displacements(send_counts);
    const auto rdispl = displacements(recv_counts);
    std::vector<double> received(layout.recv_local_rows().size());
    MPI_Alltoallv(im.ghost_values.data(), send_counts.data(), sdispl.data(), MPI_DOUBLE,
                  received.data(), recv_counts.data(), rdispl.data(), MPI_DOUBLE, MPI_COMM_WORLD);
    const auto& lrows = layout.recv_local_rows();
    const auto& lcols = layout.recv_local_cols();
    for (std::size_t k = 0; k < received.size(); ++k)
      im.matrix->sumIntoLocalValues(lrows[k], 1, &received[k], &lcols[k], false);
  }
  im.matrix->fillComplete(im.row_map, im.row_map);
  im.assembling = false;
}

void SparseMatrix::multiply(const DistributedVector& x, DistributedVector& y) const {
  auto& im = *impl_;
  if (im.assembling) throw Error("SparseMatrix::multiply before finish_assembly()");
  if (x.distribution() != im.dist || y.distribution() != im.dist)
    throw Error("SparseMatrix::multiply: vector distribution differs from the matrix's");
  if (im.x_work.is_null()) {
    im.x_work = Teuchos::rcp(new detail::Vector(im.row_map));
    im.y_work = Teuchos::rcp(new detail::Vector(im.row_map));
  }
  detail::copy_to_tpetra(x, *im.x_work);
  im.matrix->apply(*im.x_work, *im.y_work);
  detail::copy_from_tpetra(*im.y_work, y);
}

DistributedVector SparseMatrix::diagonal() const {
  auto& im = *impl_;
  if (im.assembling) throw Error("SparseMatrix::diagonal before finish_assembly()");
  detail::Vector d(im.row_map);
  im.matrix->getLocalDiagCopy(d);
  DistributedVector out(im.dist);
  detail::copy_from_tpetra(d, out);
  return out;
}

} // namespace bipot
