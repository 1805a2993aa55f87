#pragma once
/// Node-to-node discretisation of interfaces (docs/formulation.md §1, §5, §6): split a conforming
/// mesh along the interfaces between regions (or pair two coincident facet sets), then give
/// every matched node pair its weight A_i = ∫_Γ N_i dΓ and a local orthonormal frame.

#include "contact/interface/interface_spec.hpp"
#include "fem/core/types.hpp"
#include "fem/element/kinematics.hpp"
#include "fem/mesh/mesh.hpp"

#include <array>
#include <string>
#include <vector>

namespace bipot::contact {

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
struct Interface {
  std::string name;
  std::vector<InterfacePair> pairs; ///< ordered by increasing node_a
  /// Body-1 side facets (nodes of body 1, outward of body 1 = oriented like the normals), for
  /// output as a line/surface mesh and for recomputing weights.
  std::vector<Facet> facets_a;
  double initial_gap = 0; ///< m, added to g_n
  bool obstacle = false;  ///< body 2 is a rigid obstacle: every node_b is rigid_obstacle
};

/// Builds the interfaces `defs` (in that order) on `mesh`, splitting it where needed.
///
/// Region mode ("between: [a, b]"): the facets shared by a region-a and a region-b cell are
/// found on the mesh as given. Unless `tie_only`, every node of those facets is duplicated:
/// the copy (a new id at the end of mesh.nodes, same coordinates) replaces the node in every
/// region-b cell that uses it; region-a cells and all other regions keep the original. Facet
/// sets follow their cell (facets without a cell go to region b when a region-b cell holds all
/// their corners); a node set holding an original node also receives its copy. When several
/// interfaces share body 1 (a pile in layered soil), a node gets one copy per body 1, shared by
/// all regions across, so the layers stay connected to each other. With `tie_only` (perfect
/// bonding) nothing is split and every pair has node_a == node_b.
///
/// Facet-set mode: each node of facet set a is paired with the node of facet set b at the
/// same position (within 1e-9 × the mesh's bounding-box diagonal) or, with Pairing::Normal,
/// with the node of b on the line through it along its normal n (see InterfacePair; within
/// 1e-6 × the diagonal of that line; the nearest along the line if several), whose distance
/// (x_b − x_a)·n becomes the pair's gap (< 0 for overlapping bodies). Without `tie_only` the
/// mesh is not changed; with it (perfect bonding) every pair's two nodes are merged into one
/// (merge_nodes(): node ids after them shift down), so the bodies share the interface nodes as
/// in region mode and node_a == node_b; a pair more than 1e-9 × the diagonal apart along the
/// normal is an InputError (gluing it would move a node).
/// Either way the pairing must be one-to-one and cover both sets. Facets of set a without a
/// cell are oriented outward of the cell holding them.
///
/// Obstacle mode (facet set a and a RigidObstacle): each node of set a is paired with the
/// obstacle (node_b = rigid_obstacle); the pair's gap is the node's signed distance from the
/// surface and its normal the obstacle's normal at the closest point, reversed (from body 1
/// into the obstacle); the weight is that of the other modes. The mesh is not changed.
/// With `tie_only` every node must lie on the surface (within 1e-9 × the diagonal): the
/// caller holds them to the obstacle.
///
/// Weights, normals and tangents: see InterfacePair. Straight Line2/Line3 facets (and planar
/// Tri3/Quad4 faces) are integrated exactly; Line3 corner nodes get L/6, mid-nodes 2L/3.
///
/// Throws bipot::InputError, with every problem prefixed by `<where>: interface '<name>': `,
/// for: both or neither mode given, an unknown region or facet set (listing the known ones and
/// the nearest name), a node of an obstacle interface at a circle's or sphere's centre or on a
/// cylinder's axis, or off the surface of a tied one, a region paired with itself, regions that do
/// not touch, duplicate interface names, facet sets without coincident partners (listing up to 5
/// lonely nodes and the counts), nodes of set a with no node of b on their normal line or nodes of
/// b that are no node's partner or two nodes' (the same way), or a node whose facets' normals
/// cancel. Throws bipot::Error if the mesh's dimension does not match `kin`. On any exception
/// `mesh` is left unchanged.
std::vector<Interface> split_interfaces(Mesh& mesh, Kinematics kin,
                                        const std::vector<InterfaceDefinition>& defs,
                                        bool tie_only);

} // namespace bipot::contact
