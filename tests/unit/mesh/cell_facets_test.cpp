#include "fem/mesh/cell_facets.hpp"

#include "fem/core/error.hpp"
#include "mesh_test_utils.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

/// A mesh holding one Gmsh reference cell of the given type.
Mesh reference_cell(CellType type) {
  Mesh m;
  m.dim = cell_dim(type);
  switch (type) {
  case CellType::Tri3:
    m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    break;
  case CellType::Tri6:
    m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}};
    break;
  case CellType::Quad4:
    m.nodes = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    break;
  case CellType::Quad8:
    m.nodes = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0},
               {0, -1, 0},  {1, 0, 0},  {0, 1, 0}, {-1, 0, 0}};
    break;
  case CellType::Tet4:
    m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    break;
  case CellType::Hex8:
    m.nodes = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    break;
  default:
    break;
  }
  std::vector<Index> ids(m.nodes.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    ids[i] = Index(i);
  m.add_cell(type, ids, m.region_id("body"));
  return m;
}

/// Outward unit normals of the reference cells' facets, in cell_facets() order (closed form).
std::vector<std::array<double, 3>> expected_normals(CellType type) {
  const double s2 = 1.0 / std::sqrt(2.0), s3 = 1.0 / std::sqrt(3.0);
  switch (type) {
  case CellType::Tri3:
  case CellType::Tri6:
    return {{0, -1, 0}, {s2, s2, 0}, {-1, 0, 0}};
  case CellType::Quad4:
  case CellType::Quad8:
    return {{0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  case CellType::Tet4:
    return {{0, 0, -1}, {0, -1, 0}, {-1, 0, 0}, {s3, s3, s3}};
  case CellType::Hex8:
    return {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  default:
    return {};
  }
}

class ReferenceCellFacets : public ::testing::TestWithParam<CellType> {};

TEST_P(ReferenceCellFacets, OutwardNormalsMatchClosedForm) {
  const CellType type = GetParam();
  const Mesh m = reference_cell(type);
  const auto facets = boundary_facets(m);
  const auto expected = expected_normals(type);
  ASSERT_EQ(facets.size(), expected.size());
  ASSERT_EQ(cell_facets(type).size(), expected.size());
  const auto xc = test::centroid(m, test::cell_node_list(m, 0));
  for (std::size_t f = 0; f < facets.size(); ++f) {
    EXPECT_EQ(facets[f].cell, 0);
    EXPECT_EQ(facets[f].type, facet_type(type));
    ASSERT_EQ(int(facets[f].nodes.size()), num_nodes(facet_type(type)));
    const auto n = facet_normal(m, facets[f]);
    const auto xf = test::centroid(m, facets[f].nodes);
    double outward = 0.0;
    for (int k = 0; k < 3; ++k) {
      // Reference coordinates are exact binary numbers: only the normalisation rounds.
      EXPECT_NEAR(n[k], expected[f][k], 1e-15) << to_string(type) << " facet " << f;
      outward += n[k] * (xf[k] - xc[k]);
    }
    EXPECT_GT(outward, 0.0);
  }
}

TEST_P(ReferenceCellFacets, MidNodesAndQuadFacesAreConsistent) {
  const CellType type = GetParam();
  const Mesh m = reference_cell(type);
  for (const auto& local : cell_facets(type)) {
    if (local.size() == 3 && facet_type(type) == CellType::Line3) {
      for (int k = 0; k < 3; ++k) // exact halves of exact coordinates
        EXPECT_EQ(m.nodes[local[2]][k], 0.5 * (m.nodes[local[0]][k] + m.nodes[local[1]][k]));
    }
    if (local.size() == 4) { // a cyclic quad: consecutive corners differ in one coordinate
      for (int a = 0; a < 4; ++a) {
        int differ = 0;
        for (int k = 0; k < 3; ++k)
          differ += m.nodes[local[a]][k] != m.nodes[local[(a + 1) % 4]][k];
        EXPECT_EQ(differ, 1);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllCells, ReferenceCellFacets,
                         ::testing::Values(CellType::Tri3, CellType::Tri6, CellType::Quad4,
                                           CellType::Quad8, CellType::Tet4, CellType::Hex8),
                         [](const auto& info) { return to_string(info.param); });

TEST(FacetType, MapsEveryCellType) {
  EXPECT_EQ(facet_type(CellType::Tri3), CellType::Line2);
  EXPECT_EQ(facet_type(CellType::Quad4), CellType::Line2);
  EXPECT_EQ(facet_type(CellType::Tri6), CellType::Line3);
  EXPECT_EQ(facet_type(CellType::Quad8), CellType::Line3);
  EXPECT_EQ(facet_type(CellType::Tet4), CellType::Tri3);
  EXPECT_EQ(facet_type(CellType::Hex8), CellType::Quad4);
  EXPECT_THROW(facet_type(CellType::Point1), Error);
  EXPECT_THROW(cell_facets(CellType::Point1), Error);
}

/// Two unit squares side by side, [0,1]x[0,1] in region "a" and [1,2]x[0,1] in "b".
Mesh two_squares() {
  Mesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  m.add_cell(CellType::Quad4, {0, 1, 4, 3}, m.region_id("a"));
  m.add_cell(CellType::Quad4, {1, 2, 5, 4}, m.region_id("b"));
  return m;
}

TEST(BoundaryFacets, TwoSquaresHaveSixOuterEdges) {
  const Mesh m = two_squares();
  const auto b = boundary_facets(m);
  ASSERT_EQ(b.size(), 6u);
  double perimeter = 0.0;
  for (const Facet& f : b) {
    const auto& p = m.nodes[f.nodes[0]];
    const auto& q = m.nodes[f.nodes[1]];
    perimeter += std::hypot(q[0] - p[0], q[1] - p[1]);
    EXPECT_FALSE(p[0] == 1.0 && q[0] == 1.0) << "the shared edge is not a boundary";
  }
  EXPECT_NEAR(perimeter, 6.0, 1e-15); // 2 x (2 + 1), unit lengths are exact
}

TEST(RegionInterfaceFacets, OrientedOutwardOfRegionA) {
  const Mesh m = two_squares();
  const auto ab = region_interface_facets(m, m.regions.at("a"), m.regions.at("b"));
  ASSERT_EQ(ab.size(), 1u);
  EXPECT_EQ(ab[0].cell, 0);
  EXPECT_EQ(ab[0].nodes, (std::vector<Index>{1, 4})); // a->b upward: normal (1, 0)
  const auto n = facet_normal(m, ab[0]);
  EXPECT_EQ(n[0], 1.0);
  EXPECT_EQ(n[1], 0.0);
  const auto ba = region_interface_facets(m, m.regions.at("b"), m.regions.at("a"));
  ASSERT_EQ(ba.size(), 1u);
  EXPECT_EQ(ba[0].cell, 1);
  EXPECT_EQ(facet_normal(m, ba[0])[0], -1.0);
  EXPECT_THROW(region_interface_facets(m, 0, 0), InputError);
}

TEST(BoundaryFacets, NonManifoldEdgeIsAnError) {
  Mesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {-1, 0, 0}};
  const int r = m.region_id("r");
  m.add_cell(CellType::Tri3, {0, 1, 2}, r);
  m.add_cell(CellType::Tri3, {0, 3, 1}, r);
  m.add_cell(CellType::Tri3, {0, 1, 4}, r); // third cell on edge 0-1
  try {
    boundary_facets(m);
    FAIL() << "expected bipot::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("more than two cells"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace bipot
