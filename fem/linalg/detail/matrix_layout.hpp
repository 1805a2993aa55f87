#pragma once
/// Internal to fem/linalg: the distributed structure of a SparseMatrix, computed from the
/// local SparsityPattern with plain MPI (no Trilinos here).

#include "fem/linalg/dof_distribution.hpp"
#include "fem/linalg/sparsity_pattern.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace bipot::detail {

/// Owned rows are the DOFs of this rank's DofDistribution block; ghost rows are rows touched
/// by the local pattern but owned elsewhere. Ghost-row values are assembled into a local buffer
/// and sent to their owners by finish_assembly(); this class fixes the order of that buffer on
/// the sender and where each received value goes on the owner.
///
/// Owned-row columns use a local column numbering: owned DOFs first (local index = dof -
/// first_owned_dof), then the remote columns in ascending global order, which is also
/// ascending owner order because ownership blocks are contiguous.
class MatrixLayout {
public:
  /// Collective over MPI_COMM_WORLD. Throws bipot::Error on every rank if any rank's pattern
  /// names a DOF >= num_global_dofs.
  MatrixLayout(const DofDistribution& dist, const SparsityPattern& pattern);

  const DofDistribution& distribution() const { return dist_; }

  /// Ghost rows (ascending), and their columns (global, ascending per row) in CSR form.
  const std::vector<Index>& ghost_rows() const { return ghost_rows_; }
  const std::vector<Index>& ghost_offsets() const { return ghost_offsets_; }
  const std::vector<Index>& ghost_cols() const { return ghost_cols_; }
  /// Position of ghost row `row` in ghost_rows(), or -1.
  Index ghost_index(Index row) const;

  /// The local columns are the owned DOFs, in order, then these remote ones, ascending. Only
  /// the remote ones are stored: a list of every column is a whole-mesh array (7.5 MB at 1M
  /// DOFs) per matrix.
  const std::vector<Index>& remote_columns() const { return remote_columns_; }
  /// Local column index of a global column, or -1 if no owned row uses it.
  int local_column(Index gid) const;

  /// Number of entries in each owned row (until visit_owned_rows()), and in all of them.
  const std::vector<std::size_t>& owned_row_sizes() const { return row_sizes_; }
  std::size_t num_owned_entries() const { return owned_entries_; }
  /// Calls visit(local_row, local_cols) for each owned row in order, local_cols being the
  /// row's local column indices, ascending. Call once: it frees the work arrays.
  void visit_owned_rows(const std::function<void(int, const std::vector<int>&)>& visit);

  /// Ghost values sent to / received from each rank by finish_assembly (counts of doubles).
  /// The ghost value buffer is ordered like ghost_cols(), which groups entries by owner.
  const std::vector<int>& send_counts() const { return send_counts_; }
  const std::vector<int>& recv_counts() const { return recv_counts_; }
  /// For the k-th received value (sources in rank order): owned local row and local column.
  const std::vector<int>& recv_local_rows() const { return recv_local_rows_; }
  const std::vector<int>& recv_local_cols() const { return recv_local_cols_; }

private:
  void gather_row(Index local_row, std::vector<Index>& out) const;

  DofDistribution dist_;
  std::vector<Index> ghost_rows_, ghost_offsets_, ghost_cols_;
  std::vector<Index> remote_columns_;
  std::size_t owned_entries_ = 0;
  std::vector<std::size_t> row_sizes_;
  std::vector<int> send_counts_, recv_counts_;
  std::vector<int> recv_local_rows_, recv_local_cols_;

  // Work arrays for the owned rows, freed by visit_owned_rows(). Adjacency lists in CSR form:
  // cells, couplings and received ghost segments touching each owned row.
  const SparsityPattern* pattern_;
  std::vector<Index> cell_ptr_, cell_list_;
  std::vector<Index> coupling_ptr_, coupling_list_;
  std::vector<Index> received_ptr_, received_list_;
  std::vector<Index> received_offsets_, received_cols_;
};

} // namespace bipot::detail
