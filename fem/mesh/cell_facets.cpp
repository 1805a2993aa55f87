#include "fem/mesh/cell_facets.hpp"

#include "fem/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

namespace bipot {

namespace {

std::vector<std::vector<int>> make_facets(CellType cell) {
  switch (cell) {
  case CellType::Line2:
  case CellType::Line3:
    return {{0}, {1}};
  case CellType::Tri3:
    return {{0, 1}, {1, 2}, {2, 0}};
  case CellType::Tri6:
    return {{0, 1, 3}, {1, 2, 4}, {2, 0, 5}};
  case CellType::Quad4:
    return {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  case CellType::Quad8:
    return {{0, 1, 4}, {1, 2, 5}, {2, 3, 6}, {3, 0, 7}};
  // Gmsh tets have (x1-x0) x (x2-x0) pointing towards node 3, hence face 0-2-1 for the
  // outward normal of the face opposite node 3.
  case CellType::Tet4:
    return {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  case CellType::Hex8:
    return {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  case CellType::Point1:
    break;
  }
  return {};
}

/// The facet lists of every cell type, built once: the mesh loops call this per cell.
const std::vector<std::vector<int>>& facet_table(CellType cell) {
  static const auto table = [] {
    std::map<CellType, std::vector<std::vector<int>>> t;
    for (CellType type : {CellType::Line2, CellType::Line3, CellType::Tri3, CellType::Tri6,
                          CellType::Quad4, CellType::Quad8, CellType::Tet4, CellType::Hex8})
      t[type] = make_facets(type);
    return t;
  }();
  const auto it = table.find(cell);
  if (it == table.end()) throw Error("cell_facets: a " + to_string(cell) + " cell has no facets");
  return it->second;
}

} // namespace

std::vector<std::vector<int>> cell_facets(CellType cell) {
  return facet_table(cell);
}

CellType facet_type(CellType cell) {
  switch (cell) {
  case CellType::Line2:
  case CellType::Line3:
    return CellType::Point1;
  case CellType::Tri3:
  case CellType::Quad4:
    return CellType::Line2;
  case CellType::Tri6:
  case CellType::Quad8:
    return CellType::Line3;
  case CellType::Tet4:
    return CellType::Tri3;
  case CellType::Hex8:
    return CellType::Quad4;
  case CellType::Point1:
    break;
  }
  throw Error("facet_type: a " + to_string(cell) + " cell has no facets");
}

int num_corners(CellType type) {
  switch (type) {
  case CellType::Point1:
    return 1;
  case CellType::Line2:
  case CellType::Line3:
    return 2;
  case CellType::Tri3:
  case CellType::Tri6:
    return 3;
  case CellType::Quad4:
  case CellType::Quad8:
    return 4;
  case CellType::Tet4:
    return 4;
  case CellType::Hex8:
    return 8;
  }
  return 0;
}

namespace {

/// The (at most two) cells seen so far on one facet.
struct FacetUse {
  Index cell[2] = {-1, -1};
  int count = 0;
};

using FacetMap = std::unordered_map<FacetKey, FacetUse, FacetKeyHash>;

FacetKey facet_key(const Mesh& mesh, Index c, const std::vector<int>& local, int corners) {
  Index ids[4];
  for (int i = 0; i < corners; ++i)
    ids[i] = mesh.cell(c)[local[i]];
  return bipot::facet_key(ids, corners);
}

Facet make_facet(const Mesh& mesh, Index c, CellType type, const std::vector<int>& local) {
  Facet f;
  f.type = type;
  f.cell = c;
  f.nodes.reserve(local.size());
  for (int i : local)
    f.nodes.push_back(mesh.cell(c)[i]);
  return f;
}

/// Counts the cells on every facet of the mesh.
FacetMap build_facet_map(const Mesh& mesh) {
  FacetMap map;
  map.reserve(static_cast<std::size_t>(mesh.num_cells()) * 4);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const CellType ft = facet_type(mesh.cell_types[c]);
    for (const auto& local : facet_table(mesh.cell_types[c])) {
      FacetUse& use = map[facet_key(mesh, c, local, num_corners(ft))];
      if (use.count == 2)
        throw Error("mesh: a facet of cell " + std::to_string(c) +
                    " is shared by more than two cells (non-manifold mesh)");
      use.cell[use.count++] = c;
    }
  }
  return map;
}

} // namespace

std::vector<Facet> boundary_facets(const Mesh& mesh) {
  const FacetMap map = build_facet_map(mesh);
  std::vector<Facet> out;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const CellType ft = facet_type(mesh.cell_types[c]);
    for (const auto& local : facet_table(mesh.cell_types[c]))
      if (map.at(facet_key(mesh, c, local, num_corners(ft))).count == 1)
        out.push_back(make_facet(mesh, c, ft, local));
  }
  return out;
}

std::vector<Facet> region_interface_facets(const Mesh& mesh, int region_a, int region_b) {
  if (region_a == region_b)
    throw InputError("region_interface_facets: the two regions must differ (both are " +
                     std::to_string(region_a) + ")");
  const FacetMap map = build_facet_map(mesh);
  std::vector<Facet> out;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_regions[c] != region_a) continue;
    const CellType ft = facet_type(mesh.cell_types[c]);
    for (const auto& local : facet_table(mesh.cell_types[c])) {
      const FacetUse& use = map.at(facet_key(mesh, c, local, num_corners(ft)));
      if (use.count != 2) continue;
      const Index other = use.cell[0] == c ? use.cell[1] : use.cell[0];
      if (mesh.cell_regions[other] == region_b) out.push_back(make_facet(mesh, c, ft, local));
    }
  }
  return out;
}

std::array<double, 3> facet_normal(const Mesh& mesh, const Facet& facet) {
  auto x = [&](int i) { return mesh.nodes[facet.nodes[i]]; };
  auto sub = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  auto cross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                 a[0] * b[1] - a[1] * b[0]};
  };
  std::array<double, 3> n{0.0, 0.0, 0.0};
  switch (facet.type) {
  case CellType::Line2:
  case CellType::Line3: {
    const auto t = sub(x(1), x(0));
    n = {t[1], -t[0], 0.0};
    break;
  }
  case CellType::Tri3:
  case CellType::Tri6:
    n = cross(sub(x(1), x(0)), sub(x(2), x(0)));
    break;
  // The diagonals' cross product is twice the vector area of any (even warped) quad.
  case CellType::Quad4:
  case CellType::Quad8:
    n = cross(sub(x(2), x(0)), sub(x(3), x(1)));
    break;
  default:
    throw Error("facet_normal: a " + to_string(facet.type) + " facet has no normal");
  }
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(len > 0.0))
    throw Error("facet_normal: degenerate facet of cell " + std::to_string(facet.cell));
  for (double& v : n)
    v /= len;
  return n;
}

FacetKey facet_key(const Index* corners, int count) {
  // Padding with the largest index keeps it last when the whole key is sorted.
  constexpr Index pad = std::numeric_limits<Index>::max();
  FacetKey key{pad, pad, pad, pad};
  std::copy(corners, corners + count, key.begin());
  std::sort(key.begin(), key.end());
  return key;
}

} // namespace bipot
