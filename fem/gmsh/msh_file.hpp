#pragma once
/// The content of a Gmsh MSH 4.1 file (ASCII or binary) that bipot uses, read by a strict
/// parser of bipot's own: libgmsh's reader trusts the file and corrupts memory on malformed
/// ones (docs/testing.md), so a .msh file is never handed to it.

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace bipot::msh {

using DimTag = std::pair<int, int>; ///< (dimension, tag) of an entity or a physical group

/// Elements of one block of $Elements: one entity, one element type.
struct ElementBlock {
  int dim = 0;    ///< entity dimension = element dimension
  int entity = 0; ///< entity tag
  int type = 0;   ///< Gmsh element type
  int nodes_per_element = 0;
  std::vector<std::size_t> tags;  ///< element tags
  std::vector<std::size_t> nodes; ///< node tags, nodes_per_element per element
  std::size_t pos = 0;            ///< byte offset of the block header, for messages
};

struct File {
  std::map<DimTag, std::string> physical_names;
  /// Physical tags of each entity of $Entities (empty map if the file has no $Entities).
  std::map<DimTag, std::vector<int>> entity_physicals;
  std::vector<std::size_t> node_tags;
  std::vector<std::array<double, 3>> node_coords;       ///< per node_tags entry
  std::unordered_map<std::size_t, std::size_t> node_of; ///< node tag -> index in node_tags
  std::vector<ElementBlock> element_blocks;             ///< file order
};

/// Parses `text`, the bytes of the file `path`. Refuses, with an InputError
/// "path:line: what is wrong", anything but a well-formed MSH 4.1 file: section markers
/// unpaired or out of order, counts that disagree with the entries that follow or exceed what
/// the file can hold, tags out of range or repeated, references to undefined entities or
/// nodes, unknown element types, malformed physical names, non-finite node coordinates.
File parse(const std::string& path, std::string_view text);

/// Longest physical name accepted (Gmsh's own limit).
constexpr std::size_t kMaxNameLength = 127;

} // namespace bipot::msh
