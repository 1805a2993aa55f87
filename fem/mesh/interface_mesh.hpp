#pragma once
/// A discretised interface as the FE core holds it: matched node pairs with their weights and
/// local frames, and body 1's facets. contact/interface builds it by splitting a mesh along the
/// interfaces of the input (split_interfaces()); the contact module enforces a law on it.

#include "fem/core/types.hpp"
#include "fem/mesh/mesh.hpp"

#include <array>
#include <string>
#include <vector>

namespace bipot {

/// A matched pair of nodes, node_a on body 1 and node_b on body 2: at the same position, or
/// (normal pairing) node_b on the line through node_a along `normal`, `gap` away.
struct InterfacePair {
  /// Equal for a tied (not split) interface; node_b is -1 (rigid_obstacle) when body 2 is a
  /// rigid obstacle: the pair's body-2 point is the obstacle's closest point, whose
  /// displacement is the obstacle's (data, no DOFs).
  Index node_a = -1, node_b = -1;
  /// m: (x_b − x_a)·n of the undeformed mesh, added to g_n with the interface's initial_gap;
  /// 0 unless the facet sets were paired along the normals (> 0 for bodies apart).
  double gap = 0;
  /// A_i = ∫_Γ N_i dΓ over the body-1 facets: m² in 3D and axisymmetry (2π r included), m per
  /// unit thickness in plane strain. May be 0 for a node on the axis in axisymmetry.
  double weight = 0;
  /// Unit normal pointing from body 1 into body 2: the average of the adjacent body-1 facets'
  /// outward normals weighted by their share of A_i (precisely ∫ N_i n dΓ / ‖∫ N_i n dΓ‖).
  std::array<double, 3> normal{0, 0, 0};
  /// Orthonormal tangents completing the local frame [n, t1, t2] (see complete_frame()):
  /// 2D t1 = (−n_y, n_x) so that (n, t1) is right-handed; 3D t1 × t2 = n. t2 is 0 in 2D.
  std::array<double, 3> tangent1{0, 0, 0}, tangent2{0, 0, 0};
};

/// node_b of a pair whose body 2 is a rigid obstacle.
constexpr Index rigid_obstacle = -1;

/// One discretised interface.
struct InterfaceMesh {
  std::string name;
  std::vector<InterfacePair> pairs; ///< ordered by increasing node_a
  /// Body-1 side facets (nodes of body 1, outward of body 1 = oriented like the normals), for
  /// output as a line/surface mesh and for recomputing weights.
  std::vector<Facet> facets_a;
  double initial_gap = 0; ///< m, added to g_n
  bool obstacle = false;  ///< body 2 is a rigid obstacle: every node_b is rigid_obstacle
};

/// Whether the interface's bodies share its nodes (every pair has node_a == node_b): built
/// with tie_only, for an interface bonded in every stage.
bool shares_nodes(const InterfaceMesh& iface);

} // namespace bipot
