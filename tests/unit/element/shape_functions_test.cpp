#include "fem/element/shape_functions.hpp"

#include "fem/core/error.hpp"
#include "test_cells.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace bipot {
namespace {

// Interior sample points of each reference cell (only the first cell_dim components used).
std::vector<std::array<double, 3>> sample_points(CellType type) {
  switch (cell_dim(type)) {
  case 1:
    return {{-0.7, 0, 0}, {0.13, 0, 0}, {0.61, 0, 0}};
  case 2:
    if (type == CellType::Tri3 || type == CellType::Tri6)
      return {{0.2, 0.3, 0}, {0.61, 0.17, 0}, {0.05, 0.9, 0}};
    return {{-0.7, 0.4, 0}, {0.13, -0.55, 0}, {0.61, 0.83, 0}};
  default:
    if (type == CellType::Tet4) return {{0.2, 0.3, 0.1}, {0.05, 0.1, 0.7}};
    return {{-0.7, 0.4, 0.2}, {0.13, -0.55, 0.9}};
  }
}

TEST(ShapeFunctions, PartitionOfUnityAndZeroGradientSum) {
  for (CellType type : test::all_cell_types()) {
    const int nn = num_nodes(type), d = cell_dim(type);
    for (const auto& xi : sample_points(type)) {
      double N[max_cell_nodes], dN[3 * max_cell_nodes];
      shape_values(type, xi.data(), N);
      shape_gradients(type, xi.data(), dN);
      double sum = 0;
      for (int a = 0; a < nn; ++a)
        sum += N[a];
      // Sum of at most 8 O(1) terms: round-off well below 1e-14.
      EXPECT_NEAR(sum, 1.0, 1e-14) << to_string(type);
      for (int j = 0; j < d; ++j) {
        double g = 0;
        for (int a = 0; a < nn; ++a)
          g += dN[a * d + j];
        EXPECT_NEAR(g, 0.0, 1e-14) << to_string(type) << " direction " << j;
      }
    }
  }
}

TEST(ShapeFunctions, KroneckerAtReferenceNodes) {
  for (CellType type : test::all_cell_types()) {
    const auto nodes = reference_nodes(type);
    ASSERT_EQ(static_cast<int>(nodes.size()), num_nodes(type)) << to_string(type);
    for (int b = 0; b < num_nodes(type); ++b) {
      double N[max_cell_nodes];
      shape_values(type, nodes[b].data(), N);
      // Polynomials with small integer/half coefficients at exact nodes: exact up to round-off.
      for (int a = 0; a < num_nodes(type); ++a)
        EXPECT_NEAR(N[a], a == b ? 1.0 : 0.0, 1e-15)
            << to_string(type) << " N" << a << " at node " << b;
    }
  }
}

TEST(ShapeFunctions, ReferenceNodesFollowGmshOrdering) {
  // Spot checks of the documented ordering: Line3 mid-node last, Tri6 node 4 on edge 12,
  // Quad8 node 7 on edge 30, Hex8 node 6 = (1, 1, 1).
  EXPECT_EQ(reference_nodes(CellType::Line3)[2][0], 0.0);
  EXPECT_EQ(reference_nodes(CellType::Tri6)[4], (std::array<double, 3>{0.5, 0.5, 0}));
  EXPECT_EQ(reference_nodes(CellType::Quad8)[7], (std::array<double, 3>{-1, 0, 0}));
  EXPECT_EQ(reference_nodes(CellType::Hex8)[6], (std::array<double, 3>{1, 1, 1}));
  EXPECT_EQ(reference_nodes(CellType::Hex8)[3], (std::array<double, 3>{-1, 1, -1}));
}

TEST(ShapeFunctions, GradientsMatchCentralDifferences) {
  const double h = 1e-5;
  for (CellType type : test::all_cell_types()) {
    const int nn = num_nodes(type), d = cell_dim(type);
    for (const auto& xi : sample_points(type)) {
      double dN[3 * max_cell_nodes];
      shape_gradients(type, xi.data(), dN);
      for (int j = 0; j < d; ++j) {
        auto xp = xi, xm = xi;
        xp[j] += h;
        xm[j] -= h;
        double Np[max_cell_nodes], Nm[max_cell_nodes];
        shape_values(type, xp.data(), Np);
        shape_values(type, xm.data(), Nm);
        for (int a = 0; a < nn; ++a) {
          // Central differences of polynomials of degree <= 3 per variable: truncation
          // h²/6 |N'''| <= 1e-10, round-off 1e-16/h = 1e-11; 1e-7 leaves a wide margin.
          EXPECT_NEAR(dN[a * d + j], (Np[a] - Nm[a]) / (2 * h), 1e-7)
              << to_string(type) << " N" << a << " d/dxi" << j;
        }
      }
    }
  }
}

TEST(ShapeFunctions, Point1HasNoShapeFunctions) {
  const double xi[3] = {0, 0, 0};
  double N[1];
  EXPECT_THROW(shape_values(CellType::Point1, xi, N), Error);
  EXPECT_THROW(reference_nodes(CellType::Point1), Error);
}

} // namespace
} // namespace bipot
