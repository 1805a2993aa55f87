#pragma once
/// Checks of a mesh that a solve would not survive, or would survive with a silently wrong
/// answer: run by `bipot check` and before `bipot run` solves, on the mesh as split by the
/// interfaces.

#include "fem/core/types.hpp"
#include "fem/element/kinematics.hpp"
#include "fem/mesh/mesh.hpp"

#include <string>
#include <utility>
#include <vector>

namespace bipot {

/// Every problem of `mesh`, each "<where>: message" naming the node (id and coordinates, see
/// Mesh::describe_node) or the cell (id, type and region); ids count from 0 in mesh order.
/// - a node coordinate that is NaN or infinite (a grading whose ratio overflows makes them);
/// - an inverted or degenerate cell: ElementValues finds det J <= 0 (relative to the Jacobian's
///   column norms) at one of its corners or at a quadrature point of the stiffness rule for
///   `kin` — assembly would stop there, or a bow-tie would integrate to nonsense. Cells with a
///   non-finite node are left to the first check;
/// - two nodes at the same position (within 1e-9 × the bounding-box diagonal), in no common
///   cell and not joined by `joined` (directly or through a chain of pairs): the body is
///   cracked there. `joined` holds the node pairs the model joins on purpose, i.e. every
///   interface's pairs;
/// - a node used by no cell: nothing gives its displacement a stiffness (but the rigid
///   bodies' reference nodes, `reference_nodes`, whose stiffness comes from their bodies).
/// At most 10 problems of each kind are listed, then a line with the number of the others.
std::vector<std::string> mesh_problems(const Mesh& mesh, Kinematics kin,
                                       const std::vector<std::pair<Index, Index>>& joined,
                                       const std::string& where,
                                       const std::vector<Index>& reference_nodes = {});

} // namespace bipot
