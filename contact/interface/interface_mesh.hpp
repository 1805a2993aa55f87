#pragma once
/// Node-to-node discretisation of interfaces (docs/formulation.md §1, §5, §6): split a conforming
/// mesh along the interfaces between regions (or pair two coincident facet sets), then give
/// every matched node pair its weight A_i = ∫_Γ N_i dΓ and a local orthonormal frame.

#include "contact/interface/interface_spec.hpp"
#include "fem/core/types.hpp"
#include "fem/element/kinematics.hpp"
#include "fem/mesh/interface_mesh.hpp"
#include "fem/mesh/mesh.hpp"

#include <array>
#include <string>
#include <vector>

namespace bipot::contact {

// The split interface itself is mesh data of the FE core (fem/mesh/interface_mesh.hpp);
// spelled contact::X as well.
using bipot::InterfacePair;
using bipot::rigid_obstacle;
using bipot::shares_nodes;
using Interface = bipot::InterfaceMesh;

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
