#pragma once
/// Gluing a mesh at chosen node pairs (perfect bonding of separately meshed bodies).

#include "fem/mesh/mesh.hpp"

#include <utility>
#include <vector>

namespace bipot {

/// Merges each pair (a, b) of `pairs` into one node: b is replaced by a in every cell, node
/// set and facet set (chains a–b–c merge into one node), then the nodes no longer used are
/// dropped and the rest renumbered in their old order. The survivor of a group is its
/// smallest id and keeps its coordinates; the caller makes sure the pair's nodes coincide.
/// Node sets stay sorted and unique. Returns the map old id → new id (the merged ids map to
/// their survivor's new id). Throws bipot::Error for an id out of range.
std::vector<Index> merge_nodes(Mesh& mesh, const std::vector<std::pair<Index, Index>>& pairs);

} // namespace bipot
