#pragma once
/// Which MPI rank owns which global degrees of freedom.

#include "fem/core/types.hpp"

namespace bipot {

/// Row distribution of the global system: every rank owns one contiguous block of whole
/// nodes, and node `n` carries DOFs `n * dofs_per_node + c`, c = 0..dofs_per_node-1.
/// Blocks are as even as possible (sizes differ by at most one node, lower ranks take the
/// extra ones). Every query is pure arithmetic, identical on all ranks, no communication.
class DofDistribution {
public:
  /// Distribution of `num_nodes` nodes over the ranks of MPI_COMM_WORLD, seen from the
  /// calling rank (rank 0 of 1 when MPI is not initialised).
  DofDistribution(Index num_nodes, int dofs_per_node);
  /// The same distribution over `size` ranks seen from `rank` (planning, tests).
  DofDistribution(Index num_nodes, int dofs_per_node, int rank, int size);

  Index num_nodes() const { return num_nodes_; }
  int dofs_per_node() const { return dofs_per_node_; }
  /// Rank this distribution is seen from, and the number of ranks.
  int rank() const { return rank_; }
  int size() const { return size_; }

  Index num_global_dofs() const { return num_nodes_ * dofs_per_node_; }

  /// First node owned by rank `r`; first_node_of(size()) == num_nodes().
  Index first_node_of(int r) const;
  Index first_owned_node() const { return first_owned_dof_ / dofs_per_node_; }
  Index num_owned_nodes() const { return num_owned_dofs_ / dofs_per_node_; }
  Index first_owned_dof() const { return first_owned_dof_; }
  Index num_owned_dofs() const { return num_owned_dofs_; }

  /// Rank owning `node` (0 <= node < num_nodes()).
  int owner_of_node(Index node) const;
  /// Rank owning global DOF `dof` (0 <= dof < num_global_dofs()).
  int owner_of_dof(Index dof) const { return owner_of_node(dof / dofs_per_node_); }
  /// Whether the calling rank owns `dof`.
  bool owns_dof(Index dof) const {
    return dof >= first_owned_dof_ && dof < first_owned_dof_ + num_owned_dofs_;
  }

  bool operator==(const DofDistribution& o) const {
    return num_nodes_ == o.num_nodes_ && dofs_per_node_ == o.dofs_per_node_ && rank_ == o.rank_ &&
           size_ == o.size_;
  }
  bool operator!=(const DofDistribution& o) const { return !(*this == o); }

private:
  Index num_nodes_;
  int dofs_per_node_;
  int rank_;
  int size_;
  // The owned block, kept: assembly asks for it once per matrix entry, and first_node_of()
  // costs two 64-bit divisions (3-4 % of the Mohr-Coulomb pile's run time when recomputed).
  Index first_owned_dof_;
  Index num_owned_dofs_;
};

} // namespace bipot
