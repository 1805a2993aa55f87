#include "fem/assembly/dof_map.hpp"

namespace bipot {

void DofMap::cell_dofs(const Mesh& mesh, Index cell, std::vector<Index>& out) const {
  node_dofs(mesh.cell(cell), mesh.cell_num_nodes(cell), out);
}

void DofMap::node_dofs(const Index* nodes, int count, std::vector<Index>& out) const {
  out.resize(static_cast<std::size_t>(count) * dpn_);
  for (int a = 0; a < count; ++a)
    for (int i = 0; i < dpn_; ++i)
      out[a * dpn_ + i] = dof(nodes[a], i);
}

} // namespace bipot
