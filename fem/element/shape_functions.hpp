#pragma once
/// Lagrange (and Quad8 serendipity) shape functions on the Gmsh reference cells.
///
/// Reference cells and node ordering (Gmsh, equal to VTK's for these types):
/// - Line2, Line3: ξ ∈ [-1, 1]; node 0 at -1, node 1 at +1, Line3 mid-node (index 2) at 0.
/// - Tri3, Tri6: (0,0), (1,0), (0,1); Tri6 mid-nodes on edges 01, 12, 20.
/// - Quad4, Quad8: [-1, 1]²; corners (-1,-1), (1,-1), (1,1), (-1,1); Quad8 mid-nodes on edges
///   01, 12, 23, 30 (serendipity element).
/// - Tet4: unit simplex (0,0,0), (1,0,0), (0,1,0), (0,0,1).
/// - Hex8: [-1, 1]³; bottom face ζ = -1 counter-clockwise seen from +ζ, then the top face.
/// Point1 has no shape functions: the functions below throw bipot::Error for it.

#include "fem/core/cell_type.hpp"

#include <array>
#include <vector>

namespace bipot {

/// Largest number of nodes of any supported cell (Quad8, Hex8): size of fixed buffers.
constexpr int max_cell_nodes = 8;

/// Shape function values N_a(ξ) at the reference point `xi` (cell_dim(type) entries read).
/// `N` receives num_nodes(type) values.
void shape_values(CellType type, const double* xi, double* N);

/// Reference gradients ∂N_a/∂ξ_j at `xi`, written row-major: dN[a * cell_dim(type) + j].
void shape_gradients(CellType type, const double* xi, double* dN);

/// Reference coordinates of the nodes, in node order; unused components are 0.
std::vector<std::array<double, 3>> reference_nodes(CellType type);

} // namespace bipot
