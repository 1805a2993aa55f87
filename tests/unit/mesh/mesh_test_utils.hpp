#pragma once
/// Independent geometric checks shared by the mesh tests: cell measures, orientation,
/// centroids and a facet census that does not use fem/mesh/cell_facets.

#include "fem/core/cell_type.hpp"
#include "fem/mesh/mesh.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <vector>

namespace bipot::test {

/// Twice the signed area of a 2D cell's corner polygon (shoelace), x-y plane.
inline double signed_area2(const Mesh& m, Index c) {
  const int nc = (m.cell_types[c] == CellType::Quad4 || m.cell_types[c] == CellType::Quad8) ? 4 : 3;
  double s = 0.0;
  for (int a = 0; a < nc; ++a) {
    const auto& p = m.nodes[m.cell(c)[a]];
    const auto& q = m.nodes[m.cell(c)[(a + 1) % nc]];
    s += p[0] * q[1] - q[0] * p[1];
  }
  return s;
}

/// Triple product (x_b - x_0) . ((x_c - x_0) x (x_d - x_0)).
inline double triple(const Mesh& m, Index c, int b, int cc, int d) {
  const auto& x0 = m.nodes[m.cell(c)[0]];
  std::array<std::array<double, 3>, 3> e;
  const int idx[3] = {b, cc, d};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      e[i][k] = m.nodes[m.cell(c)[idx[i]]][k] - x0[k];
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
         e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
         e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

/// Area (2D) or volume (3D) of a straight-sided cell. Hexahedra are measured as the product
/// of their bounding-box extents, exact for the axis-aligned boxes the tests build.
inline double cell_measure(const Mesh& m, Index c) {
  switch (m.cell_types[c]) {
  case CellType::Tet4:
    return triple(m, c, 1, 2, 3) / 6.0;
  case CellType::Hex8: {
    double v = 1.0;
    for (int k = 0; k < 3; ++k) {
      double lo = 1e300, hi = -1e300;
      for (int a = 0; a < 8; ++a) {
        lo = std::min(lo, m.nodes[m.cell(c)[a]][k]);
        hi = std::max(hi, m.nodes[m.cell(c)[a]][k]);
      }
      v *= hi - lo;
    }
    return v;
  }
  default:
    return 0.5 * signed_area2(m, c);
  }
}

/// Positive orientation: 2D counter-clockwise, tets/hexes positive triple product at node 0.
inline bool positively_oriented(const Mesh& m, Index c) {
  switch (m.cell_types[c]) {
  case CellType::Tet4:
    return triple(m, c, 1, 2, 3) > 0.0;
  case CellType::Hex8:
    return triple(m, c, 1, 3, 4) > 0.0;
  default:
    return signed_area2(m, c) > 0.0;
  }
}

inline std::array<double, 3> centroid(const Mesh& m, const std::vector<Index>& nodes) {
  std::array<double, 3> x{0, 0, 0};
  for (Index n : nodes)
    for (int k = 0; k < 3; ++k)
      x[k] += m.nodes[n][k] / double(nodes.size());
  return x;
}

inline std::vector<Index> cell_node_list(const Mesh& m, Index c) {
  return std::vector<Index>(m.cell(c), m.cell(c) + m.cell_num_nodes(c));
}

/// Number of cells on each facet, from hand-written corner lists of the facets (sorted
/// corner ids), independent of cell_facets().
inline std::map<std::vector<Index>, int> facet_census(const Mesh& m) {
  static const std::map<CellType, std::vector<std::vector<int>>> faces = {
      {CellType::Tri3, {{0, 1}, {1, 2}, {0, 2}}},
      {CellType::Tri6, {{0, 1}, {1, 2}, {0, 2}}},
      {CellType::Quad4, {{0, 1}, {1, 2}, {2, 3}, {0, 3}}},
      {CellType::Quad8, {{0, 1}, {1, 2}, {2, 3}, {0, 3}}},
      {CellType::Tet4, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}},
      {CellType::Hex8,
       {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 4, 5}, {1, 2, 5, 6}, {2, 3, 6, 7}, {0, 3, 4, 7}}}};
  std::map<std::vector<Index>, int> count;
  for (Index c = 0; c < m.num_cells(); ++c)
    for (const auto& f : faces.at(m.cell_types[c])) {
      std::vector<Index> key;
      for (int a : f)
        key.push_back(m.cell(c)[a]);
      std::sort(key.begin(), key.end());
      ++count[key];
    }
  return count;
}

} // namespace bipot::test
