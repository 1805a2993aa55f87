#pragma once
/// Matching two lists of mesh nodes by position (the facet-set mode of interfaces).

#include "fem/core/types.hpp"
#include "fem/mesh/mesh.hpp"

#include <vector>

namespace bipot::contact {

/// For each node of `nodes_a`, the node of `nodes_b` at distance ≤ `tol` (m, Euclidean; > 0)
/// from it — the nearest if several, each node of b used at most once (first come, in the order
/// of `nodes_a`) — or -1 if there is none. Nodes are bucketed on a grid of spacing about `tol`
/// and looked up in the neighbouring buckets: O((n_a + n_b) log n_b), no O(n_a n_b) scan.
std::vector<Index> match_coincident_nodes(const Mesh& mesh, const std::vector<Index>& nodes_a,
                                          const std::vector<Index>& nodes_b, double tol);

/// Diagonal of the bounding box of all nodes of `mesh` (m; 0 for fewer than two distinct nodes).
double bounding_box_diagonal(const Mesh& mesh);

} // namespace bipot::contact
