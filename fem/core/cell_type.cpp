#include "fem/core/cell_type.hpp"

namespace bipot {

int num_nodes(CellType type) {
  switch (type) {
  case CellType::Point1:
    return 1;
  case CellType::Line2:
    return 2;
  case CellType::Line3:
    return 3;
  case CellType::Tri3:
    return 3;
  case CellType::Tri6:
    return 6;
  case CellType::Quad4:
    return 4;
  case CellType::Quad8:
    return 8;
  case CellType::Tet4:
    return 4;
  case CellType::Hex8:
    return 8;
  }
  return 0;
}

int cell_dim(CellType type) {
  switch (type) {
  case CellType::Point1:
    return 0;
  case CellType::Line2:
  case CellType::Line3:
    return 1;
  case CellType::Tri3:
  case CellType::Tri6:
  case CellType::Quad4:
  case CellType::Quad8:
    return 2;
  case CellType::Tet4:
  case CellType::Hex8:
    return 3;
  }
  return -1;
}

int cell_order(CellType type) {
  switch (type) {
  case CellType::Line3:
  case CellType::Tri6:
  case CellType::Quad8:
    return 2;
  default:
    return 1;
  }
}

std::string to_string(CellType type) {
  switch (type) {
  case CellType::Point1:
    return "point1";
  case CellType::Line2:
    return "line2";
  case CellType::Line3:
    return "line3";
  case CellType::Tri3:
    return "tri3";
  case CellType::Tri6:
    return "tri6";
  case CellType::Quad4:
    return "quad4";
  case CellType::Quad8:
    return "quad8";
  case CellType::Tet4:
    return "tet4";
  case CellType::Hex8:
    return "hex8";
  }
  return "?";
}

} // namespace bipot
