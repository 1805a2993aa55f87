#pragma once
/// What the input says about one interface, independent of how it was read (YAML, tests).

#include "contact/interface/rigid_obstacle.hpp"

#include <optional>
#include <string>

namespace bipot::contact {

/// How the facet-set mode pairs the nodes of set a with those of set b.
enum class Pairing {
  Coincident, ///< same position (within 1e-9 × the mesh's bounding-box diagonal)
  Normal      ///< on the line through the node of a along its normal; the distance is a gap
};

/// One interface between two bodies, given in exactly one of two ways:
/// - `region_a`/`region_b` ("between: [a, b]"): the facets shared by cells of two regions of a
///   conforming mesh; split_interfaces() duplicates their nodes;
/// - `facet_set_a`/`facet_set_b`: two named facet sets of distinct nodes that either coincide
///   geometrically (Pairing::Coincident) or face each other along the normals of side a
///   (Pairing::Normal: two bodies apart before contact, e.g. a cylinder above a flat).
/// Side a is body 1 (e.g. the pile), side b body 2 (e.g. the soil): the interface normal
/// points from a into b (docs/formulation.md §1).
/// A third way: `facet_set_a` alone with an `obstacle`, a rigid surface as body 2 (no mesh,
/// no DOFs; its motion is data): each node of set a is paired with the obstacle.
struct InterfaceDefinition {
  std::string name;                      ///< used in messages and output
  std::string region_a, region_b;        ///< "between: [a, b]", or both empty
  std::string facet_set_a, facet_set_b;  ///< facet-set mode, or both empty
  double initial_gap = 0;                ///< m, added to the normal jump g_n
  Pairing pairing = Pairing::Coincident; ///< facet-set mode only
  std::optional<RigidObstacle> obstacle; ///< body 2 is this rigid surface (facet_set_b empty)
  std::string where;                     ///< "file:line:col: key" for messages, may be empty
};

} // namespace bipot::contact
