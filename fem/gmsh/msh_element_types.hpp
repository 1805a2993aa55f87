#pragma once
/// The Gmsh element types a .msh file may hold (MSH 4.1, types 1-31, 92 and 93): how many
/// nodes each has and its dimension, which the reader needs to parse elements it does not
/// use, and the name Gmsh gives it, for messages.

#include <string>

namespace bipot::msh {

struct ElementType {
  int id = 0;            ///< Gmsh element type number
  int dim = 0;           ///< 0 point, 1 line, 2 surface, 3 volume
  int num_nodes = 0;     ///< nodes per element in the file
  const char* name = ""; ///< Gmsh's name, e.g. "Quadrilateral 9"
};

/// The element type with Gmsh number `id`, or nullptr if Gmsh defines none such for files.
const ElementType* element_type(long long id);

} // namespace bipot::msh
