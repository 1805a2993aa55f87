#pragma once
/// Matching two lists of mesh nodes by position (the facet-set mode of interfaces).

#include "fem/core/types.hpp"
#include "fem/mesh/mesh.hpp"

#include <array>
#include <limits>
#include <vector>

namespace bipot::contact {

/// For each node of `nodes_a`, the node of `nodes_b` at distance ≤ `tol` (m, Euclidean; > 0)
/// from it — the nearest if several, each node of b used at most once (first come, in the order
/// of `nodes_a`) — or -1 if there is none. Nodes are bucketed on a grid of spacing about `tol`
/// and looked up in the neighbouring buckets: O((n_a + n_b) log n_b), no O(n_a n_b) scan.
std::vector<Index> match_coincident_nodes(const Mesh& mesh, const std::vector<Index>& nodes_a,
                                          const std::vector<Index>& nodes_b, double tol);

/// The node of b facing a node of a along its normal (match_nodes_along_normals).
struct NormalPartner {
  Index node = -1; ///< node of b, or -1 if none lies within the tolerance of the line
  /// m: distance from the line of the chosen node, or of the nearest node of b if none
  double off_line = std::numeric_limits<double>::infinity();
  double gap = 0; ///< m: (x_b − x_a)·n, signed (< 0: b lies behind a)
};

/// For each node x_a of `nodes_a` with unit normal `normals[i]`, the node of `nodes_b` within
/// `tol` (m, > 0) of the line x_a + s n — the one with the smallest |s| if several, so a
/// surface seen twice along the line gives its near side — or none. Nodes of b may be chosen
/// by several nodes of a (the caller checks one-to-one). O(n_a n_b): interfaces are small and
/// this runs once at set-up.
std::vector<NormalPartner>
match_nodes_along_normals(const Mesh& mesh, const std::vector<Index>& nodes_a,
                          const std::vector<std::array<double, 3>>& normals,
                          const std::vector<Index>& nodes_b, double tol);

/// Diagonal of the bounding box of all nodes of `mesh` (m; 0 for fewer than two distinct nodes).
double bounding_box_diagonal(const Mesh& mesh);

} // namespace bipot::contact
