#pragma once
/// A vector distributed like the rows of a SparseMatrix.

#include "fem/core/types.hpp"
#include "fem/linalg/dof_distribution.hpp"

#include <utility>
#include <vector>

namespace bipot {

/// Global vector of DofDistribution::num_global_dofs() entries; each rank stores its owned
/// block contiguously. Assembly: add() accepts any global index; contributions to entries
/// owned elsewhere are buffered and summed into their owners by finish_assembly().
/// Reductions (norm2, dot, gather_all) and finish_assembly() are collective.
class DistributedVector {
public:
  /// Zero vector on `dist`.
  explicit DistributedVector(const DofDistribution& dist);

  const DofDistribution& distribution() const { return dist_; }
  Index num_global() const { return dist_.num_global_dofs(); }
  Index first_owned() const { return dist_.first_owned_dof(); }
  Index num_owned() const { return static_cast<Index>(owned_.size()); }

  /// All entries (and pending off-rank contributions) set to zero.
  void set_zero();
  /// Adds `value` to global entry `global` (any rank's); off-rank entries take effect at
  /// finish_assembly(). Negative indices are skipped (eliminated DOFs), like SparseMatrix.
  void add(Index global, double value);
  /// Adds values[i] to entries dofs[i], i < n (same rules as add()).
  void add(const Index* dofs, int n, const double* values);
  /// Sends buffered off-rank contributions to their owners and sums them (collective).
  void finish_assembly();

  /// Sets an owned entry; throws bipot::Error if `global` is not owned by this rank.
  void set_owned(Index global, double value);
  /// Reads an owned entry; throws bipot::Error if `global` is not owned by this rank.
  double get_owned(Index global) const;

  /// Owned entries, entry i being global index first_owned() + i.
  double* owned_values() { return owned_.data(); }
  const double* owned_values() const { return owned_.data(); }

  /// Every global entry on every rank, in global order (collective).
  std::vector<double> gather_all() const;

  /// Euclidean norm over all ranks (collective).
  double norm2() const;
  /// Dot product with `other` (same distribution) over all ranks (collective).
  double dot(const DistributedVector& other) const;
  /// this += a * x.
  void axpy(double a, const DistributedVector& x);
  /// this *= a.
  void scale(double a);
  /// this = other (same distribution).
  void copy(const DistributedVector& other);

private:
  void check_same_layout(const DistributedVector& other, const char* what) const;

  DofDistribution dist_;
  std::vector<double> owned_;
  std::vector<std::pair<Index, double>> pending_; ///< off-rank contributions
};

} // namespace bipot
