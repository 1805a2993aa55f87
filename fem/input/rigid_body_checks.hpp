#pragma once
/// Checks that every stage's displacement conditions hold each body: a free rigid-body motion
/// makes the stiffness matrix singular (the linear solver fails after pointless cut-backs) or,
/// worse, lets a solve end with a displacement of whatever size round-off picks.

#include "fem/core/types.hpp"
#include "fem/input/problem_spec.hpp"
#include "fem/mesh/mesh.hpp"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace bipot {

/// An interface that can open (any law but perfect bonding, which shares its nodes): the
/// bodies it joins may come apart, so it does not hold one body to another.
struct OpeningInterface {
  std::string name;
  /// (node of body 1, node of body 2); the second is -1 against a rigid obstacle.
  std::vector<std::pair<Index, Index>> pairs;
  /// m: the smallest initial normal opening of its pairs, initial_gap included; < 0 when the
  /// bodies start overlapping (pressed together).
  double smallest_gap = 0;
};

/// A rigid body's reference node (fem/assembly/rigid_body_constraint.hpp), for the checks:
/// its conditions (the stage's `rigid_bodies`) act on the body holding `node`.
struct ReferenceNode {
  std::string name;                     ///< the rigid body's
  Index node = -1;                      ///< one node of the rigid body
  std::array<double, 3> point{0, 0, 0}; ///< the reference point
};

/// For every stage, the bodies its displacement conditions leave free to move rigidly. A body
/// is a set of cells connected through shared nodes (a tied interface shares its nodes, so
/// the bodies it joins count as one). Its rigid motions are the translations along x and y and
/// the rotation in 2D, along z only in axisymmetry, three translations and three rotations in
/// 3D; a motion is free when it moves none of the body's DOFs that the stage fixes: the null
/// space of those rows of the rigid-mode matrix (SVD), named as translations along
/// directions and rotations about a point or axis.
///
/// A body that an opening interface joins to another is held by it as long as it is pressed
/// on; to stay conservative it is reported only when no condition of its own stops any of its
/// motions and nothing can press it: no gravity in the stage, no pressure or traction on its
/// facets, no initial stress in its regions, and no interference on its interfaces (their
/// smallest gap plus the stage's interface_gaps value, a state kept from earlier stages).
///
/// One problem per stage and body, "<stage where>: stage '<name>': the body of region(s) ...
/// (cells ...): free <motions>; ..."; at most 10, then a line with the number of the others.
/// Conditions on sets the mesh lacks are skipped (reported elsewhere).
/// A rigid obstacle holds a body like another body would; one that a stage (or an earlier
/// one) moves may press it. `held_nodes` are fixed in every component in every stage (the
/// nodes a perfectly bonded obstacle holds). A rigid body's reference node holds the body
/// its nodes belong to in the components a stage prescribes (a translation as a node at the
/// reference point would, a rotation that rotation), and a force or moment on it may press
/// that body onto its interfaces.
std::vector<std::string> free_rigid_body_modes(const ProblemSpec& spec, const Mesh& mesh,
                                               const std::vector<OpeningInterface>& interfaces,
                                               const std::vector<Index>& held_nodes = {},
                                               const std::vector<ReferenceNode>& references = {});

} // namespace bipot
