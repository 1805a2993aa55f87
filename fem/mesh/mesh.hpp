#pragma once
/// An unstructured mesh: nodes, cells tagged by region, named node sets and facet sets.
/// Replicated on every MPI rank for now (partitioning happens on degrees of freedom and cells).

#include "fem/core/cell_type.hpp"
#include "fem/core/types.hpp"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace bipot {

/// A boundary facet (edge in 2D, face in 3D) with the cell it bounds.
struct Facet {
  CellType type = CellType::Line2;
  std::vector<Index> nodes; ///< Gmsh ordering of the facet type
  Index cell = -1;          ///< adjacent cell, -1 if unknown
};

struct Mesh {
  int dim = 2; ///< spatial dimension: 2 (x, y) or (r, z); 3 (x, y, z)

  std::vector<std::array<double, 3>> nodes; ///< coordinates; unused components are 0

  std::vector<CellType> cell_types;      ///< one per cell
  std::vector<Index> cell_offsets = {0}; ///< CSR offsets into cell_nodes, size num_cells()+1
  std::vector<Index> cell_nodes;         ///< connectivity, Gmsh node ordering
  std::vector<int> cell_regions;         ///< region id per cell

  std::map<std::string, int> regions;                   ///< region name -> id
  std::map<std::string, std::vector<Index>> node_sets;  ///< sorted, unique node ids
  std::map<std::string, std::vector<Facet>> facet_sets; ///< boundary facets by name

  Index num_nodes() const { return static_cast<Index>(nodes.size()); }
  Index num_cells() const { return static_cast<Index>(cell_types.size()); }
  int cell_num_nodes(Index c) const {
    return static_cast<int>(cell_offsets[c + 1] - cell_offsets[c]);
  }
  const Index* cell(Index c) const { return cell_nodes.data() + cell_offsets[c]; }

  /// Appends a cell; returns its index.
  Index add_cell(CellType type, const std::vector<Index>& node_ids, int region);
  /// Id of a region name, creating it if new.
  int region_id(const std::string& name);
  /// Name of a region id ("" if none).
  std::string region_name(int id) const;
  /// Node ids of a facet set (sorted, unique).
  std::vector<Index> facet_set_nodes(const std::string& name) const;
  /// Node ids of the set a boundary condition names: the node set of that name, else the
  /// facet set's nodes (sorted, unique); empty if neither exists.
  std::vector<Index> set_nodes(const std::string& name) const;
  /// "node 12 at (0.5, 1.25)" — how messages name a node.
  std::string describe_node(Index id) const;
  /// Throws bipot::Error if connectivity, offsets or sets reference missing nodes/cells.
  void check_consistency() const;
};

} // namespace bipot
