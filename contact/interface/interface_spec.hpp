#pragma once
/// What the input says about one interface, independent of how it was read (YAML, tests).

#include <string>

namespace bipot::contact {

/// One interface between two bodies, given in exactly one of two ways:
/// - `region_a`/`region_b` ("between: [a, b]"): the facets shared by cells of two regions of a
///   conforming mesh; split_interfaces() duplicates their nodes;
/// - `facet_set_a`/`facet_set_b`: two named facet sets of a mesh whose nodes already coincide
///   geometrically (distinct node ids).
/// Side a is body 1 (e.g. the pile), side b body 2 (e.g. the soil): the interface normal
/// points from a into b (formulation.md §1).
struct InterfaceDefinition {
  std::string name;                     ///< used in messages and output
  std::string region_a, region_b;       ///< "between: [a, b]", or both empty
  std::string facet_set_a, facet_set_b; ///< facet-set mode, or both empty
  double initial_gap = 0;               ///< m, added to the normal jump g_n
  std::string where;                    ///< "file:line:col: key" for messages, may be empty
};

} // namespace bipot::contact
