#pragma once
/// Distorted test cells shared by the element tests: node coordinates (num_nodes x 3,
/// row-major) in r = x > 0 so that they also serve in axisymmetry.

#include "fem/core/cell_type.hpp"

#include <array>
#include <vector>

namespace bipot::test {

/// Every cell type that has shape functions.
inline const std::vector<CellType>& all_cell_types() {
  static const std::vector<CellType> t = {CellType::Line2, CellType::Line3, CellType::Tri3,
                                          CellType::Tri6,  CellType::Quad4, CellType::Quad8,
                                          CellType::Tet4,  CellType::Hex8};
  return t;
}

/// Appends the mid-points of the given corner pairs, shifted by `offsets` (curved edges).
inline void add_mid_nodes(std::vector<double>& x, const std::vector<std::array<int, 2>>& edges,
                          const std::vector<std::array<double, 2>>& offsets) {
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int a = edges[e][0], b = edges[e][1];
    x.push_back(0.5 * (x[3 * a] + x[3 * b]) + offsets[e][0]);
    x.push_back(0.5 * (x[3 * a + 1] + x[3 * b + 1]) + offsets[e][1]);
    x.push_back(0);
  }
}

/// A distorted, positively oriented cell of each 2D/3D type. Quadratic cells have curved edges.
inline std::vector<double> distorted_cell(CellType type) {
  switch (type) {
  case CellType::Tri3:
    return {0.3, 0.2, 0, 1.9, 0.5, 0, 0.8, 1.7, 0};
  case CellType::Tri6: {
    std::vector<double> x = distorted_cell(CellType::Tri3);
    add_mid_nodes(x, {{0, 1}, {1, 2}, {2, 0}}, {{0.02, -0.05}, {0.04, 0.03}, {-0.03, 0.02}});
    return x;
  }
  case CellType::Quad4:
    return {0.5, 0.1, 0, 2.0, 0.3, 0, 1.8, 1.6, 0, 0.6, 1.2, 0};
  case CellType::Quad8: {
    std::vector<double> x = distorted_cell(CellType::Quad4);
    add_mid_nodes(x, {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
                  {{0.03, -0.04}, {0.05, 0.02}, {-0.02, 0.06}, {-0.04, -0.01}});
    return x;
  }
  case CellType::Tet4:
    return {0.1, 0.2, 0.0, 1.3, 0.1, 0.2, 0.3, 1.4, 0.1, 0.2, 0.3, 1.2};
  case CellType::Hex8:
    return {0.0,  0.1, -0.05, 1.1, 0.0,  0.1,  1.2, 0.9, 0.0,  -0.1, 1.0, 0.05,
            0.05, 0.0, 1.0,   1.0, -0.1, 1.15, 1.1, 1.1, 0.95, 0.1,  0.9, 1.1};
  default:
    return {};
  }
}

} // namespace bipot::test
