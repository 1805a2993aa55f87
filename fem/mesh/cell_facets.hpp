#pragma once
/// Facets (edges of 2D cells, faces of 3D cells) of the cell types, and searches for the
/// boundary and the interfaces between regions of a mesh.
///
/// Orientation convention: every facet is listed so that its normal points OUT of its cell.
/// A line facet a->b (2D) has tangent t = x_b - x_a and outward normal (t_y, -t_x), which for
/// counter-clockwise cells is the right-hand side. A 3D facet with corners x0, x1, x2, ... has
/// outward normal (x1 - x0) x (x2 - x0).

#include "fem/core/cell_type.hpp"
#include "fem/mesh/mesh.hpp"

#include <array>
#include <functional>
#include <vector>

namespace bipot {

/// Local node indices of every facet of a cell, each in the Gmsh order of the facet type
/// (Line2: a, b; Line3: a, b, mid; Tri3; Quad4), oriented outward (see file comment).
/// Line cells have two Point1 facets. Throws bipot::Error for Point1 (no facets).
std::vector<std::vector<int>> cell_facets(CellType cell);

/// Type of the facets of a cell: Tri3/Quad4 -> Line2, Tri6/Quad8 -> Line3, Tet4 -> Tri3,
/// Hex8 -> Quad4, lines -> Point1. Throws bipot::Error for Point1.
CellType facet_type(CellType cell);

/// Number of corner (vertex) nodes of a cell type: the first nodes in Gmsh order.
int num_corners(CellType type);

/// The facets of `mesh` that belong to exactly one cell, outward-oriented, `Facet::cell` set,
/// in order of increasing cell then local facet index. Throws bipot::Error if a facet is shared
/// by more than two cells (non-manifold mesh).
std::vector<Facet> boundary_facets(const Mesh& mesh);

/// The facets shared by a cell of region `region_a` and a cell of region `region_b`, oriented
/// outward of the region-a cell, `Facet::cell` = the region-a cell, in order of increasing
/// region-a cell. Throws bipot::InputError if the two ids are equal.
std::vector<Facet> region_interface_facets(const Mesh& mesh, int region_a, int region_b);

/// Unit outward normal of a facet computed from its corner nodes (2D: (t_y, -t_x)/|t|;
/// 3D: normalised (x1 - x0) x (x2 - x0) for triangles, (x2 - x0) x (x3 - x1) for quads).
/// Throws bipot::Error for Point1 facets or a degenerate (zero-length/area) facet.
std::array<double, 3> facet_normal(const Mesh& mesh, const Facet& facet);

/// Sorted corner node ids of a facet, padded: identifies a facet whichever cell it is seen
/// from (hash-map key for facet matching).
using FacetKey = std::array<Index, 4>;
struct FacetKeyHash {
  std::size_t operator()(const FacetKey& k) const {
    std::size_t h = 0;
    for (Index v : k)
      h = h * 1000003u ^ std::hash<Index>()(v);
    return h;
  }
};
/// The key of up to four corner node ids given in any order.
FacetKey facet_key(const Index* corners, int count);

} // namespace bipot
