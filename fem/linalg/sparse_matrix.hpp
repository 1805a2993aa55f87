#pragma once
/// Distributed sparse matrix (Tpetra CRS behind a PIMPL).

#include "fem/core/types.hpp"
#include "fem/linalg/dof_distribution.hpp"
#include "fem/linalg/sparsity_pattern.hpp"

#include <memory>

namespace bipot {

class DistributedVector;

/// Square matrix whose rows are distributed per a DofDistribution. The structure is fixed at
/// construction from the pattern every rank contributes (cells may touch rows owned by other
/// ranks); values can then be assembled any number of times without rebuilding the graph:
///
///     A.set_zero();  A.add_dense(...) per cell;  A.finish_assembly();
///
/// Contributions to rows owned by other ranks are buffered locally and summed into their
/// owners by finish_assembly(). Every owned row contains its diagonal entry. Negative DOF
/// indices are skipped, as in SparsityPattern. Only the constructor, finish_assembly(),
/// multiply() and num_global_entries() are collective.
class SparseMatrix {
public:
  /// Builds the distributed graph (collective). `pattern` may be discarded afterwards.
  /// The matrix starts at zero, ready for assembly.
  SparseMatrix(const DofDistribution& dist, const SparsityPattern& pattern);
  ~SparseMatrix();
  SparseMatrix(SparseMatrix&&) noexcept;
  SparseMatrix& operator=(SparseMatrix&&) noexcept;
  SparseMatrix(const SparseMatrix&) = delete;
  SparseMatrix& operator=(const SparseMatrix&) = delete;

  const DofDistribution& distribution() const;
  Index num_global_rows() const;
  /// Stored entries over all ranks (collective).
  Index num_global_entries() const;

  /// Zeroes all values (pattern kept) and opens assembly.
  void set_zero();
  /// Adds the n x n block `values_row_major` at rows and columns `dofs[0..n)`. Throws
  /// bipot::Error naming the entry if a (row, col) pair with both indices >= 0 is not in
  /// the pattern; entries before it in this call may already have been added.
  void add_dense(const Index* dofs, int n, const double* values_row_major);
  /// Adds the rows x cols block `values_row_major` (same rules as add_dense()).
  void add_block(const Index* rows, int n_rows, const Index* cols, int n_cols,
                 const double* values_row_major);
  /// Adds one entry; throws bipot::Error if (row, col) is not in the pattern.
  void add(Index row, Index col, double value);
  /// Sums off-rank contributions into their owners and closes assembly (collective).
  void finish_assembly();

  /// y = A x (collective). x and y must have this matrix's distribution; y is overwritten.
  void multiply(const DistributedVector& x, DistributedVector& y) const;
  /// The diagonal of A.
  DistributedVector diagonal() const;

  struct Impl;

private:
  friend class LinearSolver;
  friend class SchurComplementSolver;
  std::unique_ptr<Impl> impl_;
};

} // namespace bipot
