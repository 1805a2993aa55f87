#pragma once
/// Reading Gmsh MSH 4.1 meshes with a strict parser of bipot's own (fem/gmsh/msh_file.hpp).

#include "fem/mesh/mesh.hpp"

#include <cstddef>
#include <string>

namespace bipot {

/// Largest .msh file read (bytes): the file is read whole into memory.
constexpr std::size_t kMaxMshBytes = std::size_t(2) << 30;

/// Reads a Gmsh mesh file in MSH 4.1 format (ASCII or binary, as Gmsh 4 writes it).
///
/// - The mesh dimension is the highest dimension of the physical groups that hold elements
///   (must be 2 or 3; a 2D mesh must lie in the plane z = 0).
/// - Physical groups of that dimension become regions, named by their physical name
///   ("region_<tag>" if unnamed); elements outside physical groups are ignored, an element in
///   two such groups is an error.
/// - Physical groups of dimension - 1 become facet sets (outward of the adjacent cell,
///   `Facet::cell` set; a facet between two cells is oriented outward of the cell with the
///   smaller region id, then the smaller cell index) AND node sets of the same name. Groups
///   of lower dimension (physical points, curves in 3D) become node sets. Unnamed ones are
///   called "physical_<dim>_<tag>".
/// - Nodes are renumbered 0..n-1 in increasing Gmsh tag, keeping only nodes used by cells.
/// - Cells with a negative orientation (2D: clockwise; 3D: negative volume) are re-ordered,
///   mid-side nodes included.
///
/// Supported elements: the CellType list (point, line 2/3, triangle 3/6, quadrangle 4/8,
/// tetrahedron 4, hexahedron 8); elements of other Gmsh types may be in the file outside the
/// physical groups bipot uses. Throws bipot::InputError naming the file (and the line where
/// the file is at fault) for a missing or unreadable file, a file that is not MSH 4.1, a
/// malformed file (msh::parse lists the checks), an unsupported element type in a physical
/// group (naming the type), or an inconsistent mesh. libgmsh is not used: its reader is not
/// safe on malformed files. Thread-safe (no global state).
Mesh read_gmsh(const std::string& path);

} // namespace bipot
