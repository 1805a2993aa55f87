#include "fem/linalg/dof_distribution.hpp"

#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"

#include <algorithm>
#include <string>

namespace bipot {

DofDistribution::DofDistribution(Index num_nodes, int dofs_per_node)
    : DofDistribution(num_nodes, dofs_per_node, mpi_rank(), mpi_size()) {}

DofDistribution::DofDistribution(Index num_nodes, int dofs_per_node, int rank, int size)
    : num_nodes_(num_nodes), dofs_per_node_(dofs_per_node), rank_(rank), size_(size) {
  if (num_nodes < 0 || dofs_per_node < 1 || size < 1 || rank < 0 || rank >= size)
    throw Error("DofDistribution: invalid arguments (num_nodes " + std::to_string(num_nodes) +
                ", dofs_per_node " + std::to_string(dofs_per_node) + ", rank " +
                std::to_string(rank) + " of " + std::to_string(size) + ")");
  first_owned_dof_ = first_node_of(rank) * dofs_per_node;
  num_owned_dofs_ = (first_node_of(rank + 1) - first_node_of(rank)) * dofs_per_node;
}

Index DofDistribution::first_node_of(int r) const {
  // The first `extra` ranks own base + 1 nodes, the others base.
  const Index base = num_nodes_ / size_;
  const Index extra = num_nodes_ % size_;
  return r * base + std::min<Index>(r, extra);
}

int DofDistribution::owner_of_node(Index node) const {
  if (node < 0 || node >= num_nodes_)
    throw Error("DofDistribution: node " + std::to_string(node) + " is outside [0, " +
                std::to_string(num_nodes_) + ")");
  const Index base = num_nodes_ / size_;
  const Index extra = num_nodes_ % size_;
  const Index split = extra * (base + 1); // nodes before this belong to the larger blocks
  if (node < split) return static_cast<int>(node / (base + 1));
  return static_cast<int>(extra + (node - split) / base);
}

} // namespace bipot
