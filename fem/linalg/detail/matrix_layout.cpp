#include "fem/linalg/detail/matrix_layout.hpp"

#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"

#include <mpi.h>

#include <algorithm>
#include <string>

namespace bipot::detail {

namespace {

void sort_unique(std::vector<Index>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Turns per-row counts (in ptr[1..n]) into CSR offsets.
void counts_to_offsets(std::vector<Index>& ptr) {
  for (std::size_t i = 1; i < ptr.size(); ++i)
    ptr[i] += ptr[i - 1];
}

std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> displs(counts.size(), 0);
  for (std::size_t i = 1; i < counts.size(); ++i)
    displs[i] = displs[i - 1] + counts[i - 1];
  return displs;
}

int total(const std::vector<int>& counts) {
  int sum = 0;
  for (int c : counts)
    sum += c;
  return sum;
}

// Sends `send` (grouped by destination, counts per rank) and returns what arrives,
// grouped by source rank. With one rank nothing is communicated.
std::vector<Index> exchange(const std::vector<Index>& send, const std::vector<int>& send_counts,
                            const std::vector<int>& recv_counts) {
  std::vector<Index> recv(static_cast<std::size_t>(total(recv_counts)));
  if (send_counts.size() == 1) {
    std::copy(send.begin(), send.end(), recv.begin());
    return recv;
  }
  const auto sdispl = displacements(send_counts);
  const auto rdispl = displacements(recv_counts);
  MPI_Alltoallv(send.data(), send_counts.data(), sdispl.data(), MPI_INT64_T, recv.data(),
                recv_counts.data(), rdispl.data(), MPI_INT64_T, MPI_COMM_WORLD);
  return recv;
}

std::vector<int> exchange_counts(const std::vector<int>& send_counts) {
  std::vector<int> recv_counts(send_counts.size(), 0);
  if (send_counts.size() == 1) return send_counts;
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  return recv_counts;
}

} // namespace

MatrixLayout::MatrixLayout(const DofDistribution& dist, const SparsityPattern& pattern)
    : dist_(dist), pattern_(&pattern) {
  if (dist.size() != mpi_size())
    throw Error("SparseMatrix: DofDistribution made for " + std::to_string(dist.size()) +
                " ranks used on " + std::to_string(mpi_size()));
  const Index first = dist.first_owned_dof();
  const Index n_owned = dist.num_owned_dofs();
  const Index n_global = dist.num_global_dofs();
  const auto& cell_off = pattern.cell_offsets();
  const auto& cell_dofs = pattern.cell_dofs();
  const auto& cpl_rows = pattern.coupling_rows();
  const auto& cpl_cols = pattern.coupling_cols();

  // Validate before any exchange, and agree on the verdict, so no rank waits in a collective
  // for a rank that has thrown.
  Index bad = -1;
  for (Index d : cell_dofs)
    if (d >= n_global) bad = d;
  for (Index d : cpl_rows)
    if (d >= n_global) bad = d;
  for (Index d : cpl_cols)
    if (d >= n_global) bad = d;
  if (sum_all(static_cast<Index>(bad >= 0)) > 0)
    throw Error("SparseMatrix: sparsity pattern names DOF " +
                (bad >= 0 ? std::to_string(bad) : std::string("(on another rank)")) +
                " but there are only " + std::to_string(n_global) + " DOFs");

  auto owned = [&](Index d) { return d >= first && d < first + n_owned; };
  for (Index d : cell_dofs)
    if (d >= 0 && !owned(d)) ghost_rows_.push_back(d);
  for (Index d : cpl_rows)
    if (d >= 0 && !owned(d)) ghost_rows_.push_back(d);
  sort_unique(ghost_rows_);
  const Index n_local = n_owned + static_cast<Index>(ghost_rows_.size());
  auto local_row = [&](Index d) { return owned(d) ? d - first : n_owned + ghost_index(d); };

  // Row -> cells and row -> couplings adjacency (counting sort into CSR).
  cell_ptr_.assign(static_cast<std::size_t>(n_local) + 1, 0);
  for (Index d : cell_dofs)
    if (d >= 0) ++cell_ptr_[local_row(d) + 1];
  counts_to_offsets(cell_ptr_);
  cell_list_.resize(static_cast<std::size_t>(cell_ptr_.back()));
  {
    std::vector<Index> next(cell_ptr_.begin(), cell_ptr_.end() - 1);
    for (Index c = 0; c + 1 < static_cast<Index>(cell_off.size()); ++c)
      for (Index k = cell_off[c]; k < cell_off[c + 1]; ++k)
        if (cell_dofs[k] >= 0) cell_list_[next[local_row(cell_dofs[k])]++] = c;
  }
  coupling_ptr_.assign(static_cast<std::size_t>(n_local) + 1, 0);
  for (Index d : cpl_rows)
    if (d >= 0) ++coupling_ptr_[local_row(d) + 1];
  counts_to_offsets(coupling_ptr_);
  coupling_list_.resize(static_cast<std::size_t>(coupling_ptr_.back()));
  {
    std::vector<Index> next(coupling_ptr_.begin(), coupling_ptr_.end() - 1);
    for (Index k = 0; k < static_cast<Index>(cpl_rows.size()); ++k)
      if (cpl_rows[k] >= 0) coupling_list_[next[local_row(cpl_rows[k])]++] = k;
  }
  received_ptr_.assign(static_cast<std::size_t>(n_owned) + 1, 0);

  // Ghost rows' columns: these go to the owners, whose rows must include them.
  std::vector<Index> scratch;
  ghost_offsets_.assign(1, 0);
  for (Index g = 0; g < static_cast<Index>(ghost_rows_.size()); ++g) {
    gather_row(n_owned + g, scratch);
    ghost_cols_.insert(ghost_cols_.end(), scratch.begin(), scratch.end());
    ghost_offsets_.push_back(static_cast<Index>(ghost_cols_.size()));
  }

  // Exchange: headers (row, number of columns) and the columns themselves.
  const int size = dist.size();
  std::vector<int> header_counts(size, 0);
  send_counts_.assign(size, 0);
  std::vector<Index> headers;
  for (std::size_t g = 0; g < ghost_rows_.size(); ++g) {
    const int p = dist.owner_of_dof(ghost_rows_[g]);
    const Index n = ghost_offsets_[g + 1] - ghost_offsets_[g];
    headers.push_back(ghost_rows_[g]);
    headers.push_back(n);
    header_counts[p] += 2;
    send_counts_[p] += static_cast<int>(n);
  }
  const auto recv_header_counts = exchange_counts(header_counts);
  recv_counts_ = exchange_counts(send_counts_);
  const auto recv_headers = exchange(headers, header_counts, recv_header_counts);
  received_cols_ = exchange(ghost_cols_, send_counts_, recv_counts_);
  const std::size_t n_segments = recv_headers.size() / 2;
  std::vector<Index> received_rows(n_segments);
  received_offsets_.assign(n_segments + 1, 0);
  for (std::size_t s = 0; s < n_segments; ++s) {
    received_rows[s] = recv_headers[2 * s];
    received_offsets_[s + 1] = received_offsets_[s] + recv_headers[2 * s + 1];
    ++received_ptr_[received_rows[s] - first + 1];
  }
  counts_to_offsets(received_ptr_);
  received_list_.resize(n_segments);
  {
    std::vector<Index> next(received_ptr_.begin(), received_ptr_.end() - 1);
    for (std::size_t s = 0; s < n_segments; ++s)
      received_list_[next[received_rows[s] - first]++] = static_cast<Index>(s);
  }

  // Pass 1 over the owned rows: sizes and the remote columns.
  std::vector<Index> remote;
  row_sizes_.resize(static_cast<std::size_t>(n_owned));
  for (Index r = 0; r < n_owned; ++r) {
    gather_row(r, scratch);
    row_sizes_[r] = scratch.size();
    owned_entries_ += scratch.size();
    for (Index c : scratch)
      if (!owned(c)) remote.push_back(c);
  }
  sort_unique(remote);
  remote_columns_ = std::move(remote);

  recv_local_rows_.reserve(received_cols_.size());
  recv_local_cols_.reserve(received_cols_.size());
  for (std::size_t s = 0; s < n_segments; ++s)
    for (Index k = received_offsets_[s]; k < received_offsets_[s + 1]; ++k) {
      recv_local_rows_.push_back(static_cast<int>(received_rows[s] - first));
      recv_local_cols_.push_back(local_column(received_cols_[k]));
    }
}

Index MatrixLayout::ghost_index(Index row) const {
  const auto it = std::lower_bound(ghost_rows_.begin(), ghost_rows_.end(), row);
  if (it == ghost_rows_.end() || *it != row) return -1;
  return it - ghost_rows_.begin();
}

int MatrixLayout::local_column(Index gid) const {
  const Index first = dist_.first_owned_dof();
  const Index n_owned = dist_.num_owned_dofs();
  if (gid >= first && gid < first + n_owned) return static_cast<int>(gid - first);
  const auto it = std::lower_bound(remote_columns_.begin(), remote_columns_.end(), gid);
  if (it == remote_columns_.end() || *it != gid) return -1;
  return static_cast<int>(n_owned + (it - remote_columns_.begin()));
}

void MatrixLayout::gather_row(Index local_row, std::vector<Index>& out) const {
  out.clear();
  const auto& cell_off = pattern_->cell_offsets();
  const auto& cell_dofs = pattern_->cell_dofs();
  const auto& cpl_off = pattern_->coupling_offsets();
  const auto& cpl_cols = pattern_->coupling_cols();
  const Index n_owned = dist_.num_owned_dofs();
  // Every owned row keeps its diagonal: Jacobi, ILU and Dirichlet rows rely on it.
  if (local_row < n_owned) out.push_back(dist_.first_owned_dof() + local_row);
  for (Index i = cell_ptr_[local_row]; i < cell_ptr_[local_row + 1]; ++i) {
    const Index c = cell_list_[i];
    for (Index k = cell_off[c]; k < cell_off[c + 1]; ++k)
      if (cell_dofs[k] >= 0) out.push_back(cell_dofs[k]);
  }
  for (Index i = coupling_ptr_[local_row]; i < coupling_ptr_[local_row + 1]; ++i) {
    const Index c = coupling_list_[i];
    for (Index k = cpl_off[c]; k < cpl_off[c + 1]; ++k)
      if (cpl_cols[k] >= 0) out.push_back(cpl_cols[k]);
  }
  if (local_row < n_owned)
    for (Index i = received_ptr_[local_row]; i < received_ptr_[local_row + 1]; ++i) {
      const Index s = received_list_[i];
      out.insert(out.end(), received_cols_.begin() + received_offsets_[s],
                 received_cols_.begin() + received_offsets_[s + 1]);
    }
  sort_unique(out);
}

void MatrixLayout::visit_owned_rows(
    const std::function<void(int, const std::vector<int>&)>& visit) {
  if (!pattern_) throw Error("MatrixLayout::visit_owned_rows called twice");
  const Index n_owned = dist_.num_owned_dofs();
  std::vector<Index> scratch;
  std::vector<int> local;
  for (Index r = 0; r < n_owned; ++r) {
    gather_row(r, scratch);
    local.resize(scratch.size());
    for (std::size_t k = 0; k < scratch.size(); ++k)
      local[k] = local_column(scratch[k]);
    std::sort(local.begin(), local.end());
    visit(static_cast<int>(r), local);
  }
  pattern_ = nullptr;
  for (auto* v : {&cell_ptr_, &cell_list_, &coupling_ptr_, &coupling_list_, &received_ptr_,
                  &received_list_, &received_offsets_, &received_cols_})
    std::vector<Index>().swap(*v);
  std::vector<std::size_t>().swap(row_sizes_); // the graph is built: a whole-mesh array less
}

} // namespace bipot::detail
