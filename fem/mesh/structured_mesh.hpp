#pragma once
/// Blocked structured mesh generator: a tensor grid of blocks, each block a graded structured
/// grid of cells, each block assigned to a region or left empty (a hole). Nodes are shared
/// between blocks, so the mesh is conforming.

#include "fem/core/cell_type.hpp"
#include "fem/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace bipot {

/// The subdivision of one coordinate axis into segments.
struct AxisSegments {
  std::vector<double> breaks; ///< b0 < b1 < ... (length), one more than segments
  std::vector<int> cells;     ///< number of cells of each segment (>= 1)
  /// Geometric ratio of each segment: size of cell i+1 = g * size of cell i. 1 = uniform,
  /// g < 1 refines towards the segment's end. Empty means uniform everywhere.
  std::vector<double> grading;
};

/// How each quad of the lattice is split into triangles (Tri3, Tri6).
enum class Diagonals {
  Right,       ///< 2 triangles, diagonal from the lower-left to the upper-right corner
  Left,        ///< 2 triangles, diagonal from the lower-right to the upper-left corner
  Alternating, ///< Right and Left in a checkerboard: Right where (i + j) is even
  Crossed      ///< 4 triangles around a node at the quad's centre (Tri3 only)
};

/// "right", "left", "alternating", "crossed".
const char* to_string(Diagonals diagonals);

/// Specification of a blocked structured mesh.
struct BlockMeshSpec {
  AxisSegments x, y, z;            ///< z is unused for 2D cell types
  CellType cell = CellType::Quad4; ///< Tri3, Tri6, Quad4, Quad8, Tet4 or Hex8
  /// Triangle cells only (anything but Right is an error for other types); Crossed needs Tri3.
  Diagonals diagonals = Diagonals::Right;
  /// One region name per block, x fastest, then y, then z; "" means no cells (a hole).
  std::vector<std::string> block_regions;
};

/// Builds the mesh. Quads are split into triangles (Tri3/Tri6) as `diagonals` says (by
/// default two, along the diagonal from their lower-left to their upper-right corner; Crossed
/// adds a node at the centre of each quad, the middle of its two axis intervals); hexahedra into
/// six tetrahedra around the diagonal from their (min,min,min) to their (max,max,max) corner, which
/// is conforming. 2D cells are counter-clockwise, 3D cells positively oriented (Gmsh convention).
/// Named facet sets AND node sets of the outer sides of the bounding box: "left" (x = min),
/// "right" (x = max), "bottom" (y = min), "top" (y = max), and in 3D "back" (z = min),
/// "front" (z = max); facets outward-oriented with `Facet::cell` set. Facets bounding holes
/// inside the box belong to no set. Mid-side nodes of quadratic cells lie at the geometric
/// middle of their edge. Throws bipot::InputError listing every problem of the spec.
Mesh make_block_mesh(const BlockMeshSpec& spec);

/// A single-block rectangle [x0, x1] x [y0, y1] with nx x ny cells (before triangle splitting),
/// gradings gx, gy (see AxisSegments).
Mesh make_rectangle(double x0, double x1, int nx, double y0, double y1, int ny, CellType cell,
                    const std::string& region = "body", double gx = 1.0, double gy = 1.0);

/// A single-block box [x0, x1] x [y0, y1] x [z0, z1] with nx x ny x nz cells (before
/// tetrahedral splitting), gradings gx, gy, gz.
Mesh make_box(double x0, double x1, int nx, double y0, double y1, int ny, double z0, double z1,
              int nz, CellType cell, const std::string& region = "body", double gx = 1.0,
              double gy = 1.0, double gz = 1.0);

/// Node coordinates along one axis (breaks included exactly), as used by make_block_mesh.
/// Assumes a valid AxisSegments.
std::vector<double> axis_coordinates(const AxisSegments& axis);

} // namespace bipot
