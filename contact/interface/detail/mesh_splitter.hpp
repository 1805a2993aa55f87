#pragma once
/// Splitting a conforming mesh along the interfaces between regions, one interface at a time
/// (the region mode of split_interfaces()).

#include "contact/interface/interface_mesh.hpp"
#include "fem/mesh/mesh.hpp"

#include <map>
#include <utility>
#include <vector>

namespace bipot::contact::detail {

/// Splits `mesh` (kept by reference, modified in place) interface after interface. Positions
/// are the node ids of the mesh as given at construction; cells are looked up through their
/// connectivity at that time, so facets found on the unsplit mesh stay usable after splits.
class MeshSplitter {
public:
  explicit MeshSplitter(Mesh& mesh);

  /// Builds the pairs and body-1 facets of the interface between regions `region_a` and
  /// `region_b` whose shared facets `facets` were found on the mesh as given (original ids,
  /// `Facet::cell` in region a). Unless `tie_only`, gives region b a copy of every node of
  /// the facets still shared with region a (one copy per position and body 1, reused by later
  /// interfaces with the same body 1), updates facet and node sets, and renumbers the nodes of
  /// the interfaces built before (`iface` must stay at its address while this object lives).
  /// Weights and frames are left to compute_pair_geometry().
  void split(const std::vector<Facet>& facets, int region_a, int region_b, bool tie_only,
             Interface& iface);

private:
  /// The current id of original node `v` in cell `c` (a reference into mesh_.cell_nodes).
  Index& id_in_cell(Index c, Index v);
  /// True when a cell of `region` holds all corners (current ids) of `f`.
  bool held_by_region(const Facet& f, int region) const;
  /// Replaces ids by their copies in the sets that belong to region `region_b`.
  void update_sets(const std::map<Index, Index>& copy_of, int region_b,
                   const std::vector<const Facet*>& orphans_b);

  struct Built {
    Interface* iface;
    int region_a, region_b;
  };

  Mesh& mesh_;
  std::vector<Index> original_cell_nodes_; ///< connectivity as given
  std::vector<Index> node_cell_offsets_;   ///< CSR: original node -> cells using it
  std::vector<Index> node_cells_;
  std::vector<Index> position_;                   ///< current node id -> original node id
  std::map<std::pair<Index, int>, Index> copies_; ///< (position, body-1 region) -> copy
  std::vector<Built> built_;
};

} // namespace bipot::contact::detail
