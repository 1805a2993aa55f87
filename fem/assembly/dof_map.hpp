#pragma once
/// Numbering of displacement degrees of freedom: node-major, `dofs_per_node` consecutive
/// DOFs per node (dof = node × d + component), so MueLu sees d×d nodal blocks and the row
/// distribution hands out whole nodes.

#include "fem/core/types.hpp"
#include "fem/mesh/mesh.hpp"

#include <vector>

namespace bipot {

class DofMap {
public:
  DofMap(Index num_nodes, int dofs_per_node) : num_nodes_(num_nodes), dpn_(dofs_per_node) {}

  Index dof(Index node, int component) const { return node * dpn_ + component; }
  int dofs_per_node() const { return dpn_; }
  Index num_nodes() const { return num_nodes_; }
  Index num_dofs() const { return num_nodes_ * dpn_; }

  /// DOFs of a cell, node by node, component fastest.
  void cell_dofs(const Mesh& mesh, Index cell, std::vector<Index>& out) const;
  /// DOFs of a list of nodes, node by node, component fastest.
  void node_dofs(const Index* nodes, int count, std::vector<Index>& out) const;

private:
  Index num_nodes_;
  int dpn_;
};

} // namespace bipot
