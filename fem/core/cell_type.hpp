#pragma once
/// Cell (element) types and their node orderings. Node ordering follows Gmsh, which for these
/// types is also VTK's: corners first (counter-clockwise in 2D), then edge mid-nodes in edge
/// order 01, 12, 20 (Tri6) or 01, 12, 23, 30 (Quad8).

#include <string>

namespace bipot {

enum class CellType {
  Point1,
  Line2,
  Line3,
  Tri3,
  Tri6,
  Quad4,
  Quad8,
  Tet4,
  Hex8,
};

/// Number of nodes of a cell type.
int num_nodes(CellType type);
/// Topological dimension (0 for Point1, 1 for lines, 2 for Tri/Quad, 3 for Tet/Hex).
int cell_dim(CellType type);
/// Polynomial degree of the shape functions (1 or 2).
int cell_order(CellType type);
/// "tri3", "quad8", ... as used in YAML and messages.
std::string to_string(CellType type);

} // namespace bipot
