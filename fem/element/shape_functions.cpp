#include "fem/element/shape_functions.hpp"

#include "fem/core/error.hpp"

namespace bipot {
namespace {

// Corner signs of the quadrilateral and hexahedron reference cells, in Gmsh order.
constexpr double quad_corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
// Quad8 mid-nodes on edges 01, 12, 23, 30.
constexpr double quad_mids[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
constexpr double hex_corners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
// Tri6 mid-node a+3 lies on the edge between corners tri_edges[a][0] and tri_edges[a][1].
constexpr int tri_edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};

[[noreturn]] void no_shape_functions(CellType type) {
  throw Error("shape functions are not defined for cell type " + to_string(type));
}

} // namespace

void shape_values(CellType type, const double* xi, double* N) {
  switch (type) {
  case CellType::Line2:
    N[0] = 0.5 * (1 - xi[0]);
    N[1] = 0.5 * (1 + xi[0]);
    return;
  case CellType::Line3:
    N[0] = 0.5 * xi[0] * (xi[0] - 1);
    N[1] = 0.5 * xi[0] * (xi[0] + 1);
    N[2] = 1 - xi[0] * xi[0];
    return;
  case CellType::Tri3:
    N[0] = 1 - xi[0] - xi[1];
    N[1] = xi[0];
    N[2] = xi[1];
    return;
  case CellType::Tri6: {
    const double L[3] = {1 - xi[0] - xi[1], xi[0], xi[1]}; // barycentric coordinates
    for (int a = 0; a < 3; ++a) {
      N[a] = L[a] * (2 * L[a] - 1);
      N[a + 3] = 4 * L[tri_edges[a][0]] * L[tri_edges[a][1]];
    }
    return;
  }
  case CellType::Quad4:
    for (int a = 0; a < 4; ++a)
      N[a] = 0.25 * (1 + xi[0] * quad_corners[a][0]) * (1 + xi[1] * quad_corners[a][1]);
    return;
  case CellType::Quad8:
    for (int a = 0; a < 4; ++a) {
      const double sa = quad_corners[a][0], ta = quad_corners[a][1];
      N[a] = 0.25 * (1 + xi[0] * sa) * (1 + xi[1] * ta) * (xi[0] * sa + xi[1] * ta - 1);
      const double sm = quad_mids[a][0], tm = quad_mids[a][1];
      N[a + 4] = sm == 0 ? 0.5 * (1 - xi[0] * xi[0]) * (1 + xi[1] * tm)
                         : 0.5 * (1 + xi[0] * sm) * (1 - xi[1] * xi[1]);
    }
    return;
  case CellType::Tet4:
    N[0] = 1 - xi[0] - xi[1] - xi[2];
    N[1] = xi[0];
    N[2] = xi[1];
    N[3] = xi[2];
    return;
  case CellType::Hex8:
    for (int a = 0; a < 8; ++a)
      N[a] = 0.125 * (1 + xi[0] * hex_corners[a][0]) * (1 + xi[1] * hex_corners[a][1]) *
             (1 + xi[2] * hex_corners[a][2]);
    return;
  case CellType::Point1:
    break;
  }
  no_shape_functions(type);
}

void shape_gradients(CellType type, const double* xi, double* dN) {
  switch (type) {
  case CellType::Line2:
    dN[0] = -0.5;
    dN[1] = 0.5;
    return;
  case CellType::Line3:
    dN[0] = xi[0] - 0.5;
    dN[1] = xi[0] + 0.5;
    dN[2] = -2 * xi[0];
    return;
  case CellType::Tri3:
    dN[0] = -1, dN[1] = -1;
    dN[2] = 1, dN[3] = 0;
    dN[4] = 0, dN[5] = 1;
    return;
  case CellType::Tri6: {
    const double L[3] = {1 - xi[0] - xi[1], xi[0], xi[1]};
    const double dL[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
    for (int a = 0; a < 3; ++a) {
      const int i = tri_edges[a][0], j = tri_edges[a][1];
      for (int d = 0; d < 2; ++d) {
        dN[2 * a + d] = (4 * L[a] - 1) * dL[a][d];
        dN[2 * (a + 3) + d] = 4 * (L[j] * dL[i][d] + L[i] * dL[j][d]);
      }
    }
    return;
  }
  case CellType::Quad4:
    for (int a = 0; a < 4; ++a) {
      const double sa = quad_corners[a][0], ta = quad_corners[a][1];
      dN[2 * a] = 0.25 * sa * (1 + xi[1] * ta);
      dN[2 * a + 1] = 0.25 * ta * (1 + xi[0] * sa);
    }
    return;
  case CellType::Quad8:
    for (int a = 0; a < 4; ++a) {
      const double s = xi[0], t = xi[1];
      const double sa = quad_corners[a][0], ta = quad_corners[a][1];
      dN[2 * a] = 0.25 * sa * (1 + t * ta) * (2 * s * sa + t * ta);
      dN[2 * a + 1] = 0.25 * ta * (1 + s * sa) * (s * sa + 2 * t * ta);
      const double sm = quad_mids[a][0], tm = quad_mids[a][1];
      double* g = dN + 2 * (a + 4);
      if (sm == 0) {
        g[0] = -s * (1 + t * tm);
        g[1] = 0.5 * tm * (1 - s * s);
      } else {
        g[0] = 0.5 * sm * (1 - t * t);
        g[1] = -t * (1 + s * sm);
      }
    }
    return;
  case CellType::Tet4:
    for (int k = 0; k < 12; ++k)
      dN[k] = 0;
    dN[0] = dN[1] = dN[2] = -1;
    dN[3] = dN[7] = dN[11] = 1;
    return;
  case CellType::Hex8:
    for (int a = 0; a < 8; ++a) {
      const double fx = 1 + xi[0] * hex_corners[a][0];
      const double fy = 1 + xi[1] * hex_corners[a][1];
      const double fz = 1 + xi[2] * hex_corners[a][2];
      dN[3 * a] = 0.125 * hex_corners[a][0] * fy * fz;
      dN[3 * a + 1] = 0.125 * hex_corners[a][1] * fx * fz;
      dN[3 * a + 2] = 0.125 * hex_corners[a][2] * fx * fy;
    }
    return;
  case CellType::Point1:
    break;
  }
  no_shape_functions(type);
}

std::vector<std::array<double, 3>> reference_nodes(CellType type) {
  switch (type) {
  case CellType::Line2:
    return {{-1, 0, 0}, {1, 0, 0}};
  case CellType::Line3:
    return {{-1, 0, 0}, {1, 0, 0}, {0, 0, 0}};
  case CellType::Tri3:
    return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  case CellType::Tri6:
    return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}};
  case CellType::Quad4:
  case CellType::Quad8: {
    std::vector<std::array<double, 3>> x;
    for (const auto& c : quad_corners)
      x.push_back({c[0], c[1], 0});
    if (type == CellType::Quad8)
      for (const auto& m : quad_mids)
        x.push_back({m[0], m[1], 0});
    return x;
  }
  case CellType::Tet4:
    return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  case CellType::Hex8: {
    std::vector<std::array<double, 3>> x;
    for (const auto& c : hex_corners)
      x.push_back({c[0], c[1], c[2]});
    return x;
  }
  case CellType::Point1:
    break;
  }
  no_shape_functions(type);
}

} // namespace bipot
