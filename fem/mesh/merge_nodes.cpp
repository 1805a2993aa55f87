#include "fem/mesh/merge_nodes.hpp"

#include "fem/core/error.hpp"

#include <algorithm>
#include <numeric>
#include <string>

namespace bipot {

std::vector<Index> merge_nodes(Mesh& mesh, const std::vector<std::pair<Index, Index>>& pairs) {
  const Index n = mesh.num_nodes();
  // Union–find with the smallest id as the root, so the survivor does not depend on order.
  std::vector<Index> root(n);
  std::iota(root.begin(), root.end(), Index{0});
  auto find = [&](Index i) {
    while (root[i] != i)
      i = root[i] = root[root[i]];
    return i;
  };
  for (const auto& [a, b] : pairs) {
    if (a < 0 || a >= n || b < 0 || b >= n)
      throw Error("merge_nodes: node pair (" + std::to_string(a) + ", " + std::to_string(b) +
                  ") out of range");
    const Index ra = find(a), rb = find(b);
    if (ra != rb) root[std::max(ra, rb)] = std::min(ra, rb);
  }
  std::vector<Index> new_id(n, -1);
  Index next = 0;
  for (Index i = 0; i < n; ++i)
    if (find(i) == i) {
      mesh.nodes[next] = mesh.nodes[i];
      new_id[i] = next++;
    }
  for (Index i = 0; i < n; ++i)
    new_id[i] = new_id[find(i)];
  mesh.nodes.resize(next);
  for (Index& v : mesh.cell_nodes)
    v = new_id[v];
  for (auto& [name, ids] : mesh.node_sets) {
    for (Index& v : ids)
      v = new_id[v];
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  }
  for (auto& [name, facets] : mesh.facet_sets)
    for (Facet& f : facets)
      for (Index& v : f.nodes)
        v = new_id[v];
  return new_id;
}

} // namespace bipot
