#include "fem/mesh/structured_mesh.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/cell_facets.hpp"
#include "mesh_test_utils.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace bipot {
namespace {

double total_measure(const Mesh& m) {
  double s = 0.0;
  for (Index c = 0; c < m.num_cells(); ++c)
    s += test::cell_measure(m, c);
  return s;
}

const std::vector<CellType> kAllTypes = {CellType::Tri3,  CellType::Tri6, CellType::Quad4,
                                         CellType::Quad8, CellType::Tet4, CellType::Hex8};

/// 2 x 2 (x 2) blocks with graded segments and one hole.
BlockMeshSpec holed_spec(CellType type) {
  BlockMeshSpec s;
  s.x = {{0.0, 1.0, 3.0}, {2, 3}, {1.0, 0.7}};
  s.y = {{-1.0, 1.0, 1.5}, {3, 2}, {1.3, 1.0}};
  s.z = {{0.0, 0.5, 2.0}, {1, 2}, {1.0, 1.2}};
  s.cell = type;
  if (cell_dim(type) == 2)
    s.block_regions = {"a", "b", "", "a"};
  else
    s.block_regions = {"a", "b", "", "a", "b", "b", "a", ""};
  return s;
}

TEST(BlockMesh, NodeAndCellCountsClosedForm) {
  const int nx = 3, ny = 2, nz = 4;
  const Index grid = (nx + 1) * (ny + 1), fine = (2 * nx + 1) * (2 * ny + 1);
  const Index grid3 = Index(nx + 1) * (ny + 1) * (nz + 1);
  struct Case {
    CellType type;
    Index nodes, cells;
  };
  const Case cases[] = {{CellType::Quad4, grid, nx * ny},
                        {CellType::Tri3, grid, 2 * nx * ny},
                        {CellType::Tri6, fine, 2 * nx * ny},
                        {CellType::Quad8, fine - nx * ny, nx * ny}, // no cell centres
                        {CellType::Hex8, grid3, nx * ny * nz},
                        {CellType::Tet4, grid3, 6 * nx * ny * nz}};
  for (const Case& c : cases) {
    const Mesh m = cell_dim(c.type) == 2 ? make_rectangle(0, 1, nx, 0, 2, ny, c.type)
                                         : make_box(0, 1, nx, 0, 2, ny, 0, 3, nz, c.type);
    EXPECT_EQ(m.num_nodes(), c.nodes) << to_string(c.type);
    EXPECT_EQ(m.num_cells(), c.cells) << to_string(c.type);
    EXPECT_EQ(m.dim, cell_dim(c.type));
    EXPECT_NO_THROW(m.check_consistency());
  }
}

TEST(BlockMesh, BlocksMergeNodesAtTheirBoundaries) {
  // Two blocks of 2 + 3 cells give exactly the nodes of one block of 5 cells.
  BlockMeshSpec s;
  s.x = {{0.0, 1.0, 2.5}, {2, 3}, {}};
  s.y = {{0.0, 1.0}, {2}, {}};
  s.cell = CellType::Quad8;
  s.block_regions = {"a", "b"};
  EXPECT_EQ(make_block_mesh(s).num_nodes(),
            make_rectangle(0, 2.5, 5, 0, 1, 2, CellType::Quad8).num_nodes());
}

TEST(BlockMesh, MeasureEqualsSumOfBlockMeasures) {
  // 2D: blocks (1 x 2) + (2 x 2) + hole + (2 x 0.5) = 7; 3D blocks listed x fastest.
  const double area = 1.0 * 2.0 + 2.0 * 2.0 + 2.0 * 0.5;
  const double dx[2] = {1.0, 2.0}, dy[2] = {2.0, 0.5}, dz[2] = {0.5, 1.5};
  const bool filled[8] = {true, true, false, true, true, true, true, false};
  double volume = 0.0;
  for (int b = 0; b < 8; ++b)
    if (filled[b]) volume += dx[b % 2] * dy[(b / 2) % 2] * dz[b / 4];
  for (CellType type : kAllTypes) {
    const Mesh m = make_block_mesh(holed_spec(type));
    // Sums of O(100) terms of size O(1): round-off ~1e-14, 1e-12 leaves margin.
    EXPECT_NEAR(total_measure(m), cell_dim(type) == 2 ? area : volume, 1e-12) << to_string(type);
  }
}

TEST(BlockMesh, GradingRatioAndExactSegmentEnds) {
  AxisSegments axis{{-1.0, 2.0, 2.5}, {5, 4}, {0.8, 1.25}};
  const auto x = axis_coordinates(axis);
  ASSERT_EQ(x.size(), 10u);
  EXPECT_EQ(x[0], -1.0); // breaks hit exactly, no round-off
  EXPECT_EQ(x[5], 2.0);
  EXPECT_EQ(x[9], 2.5);
  // First cell of a graded segment: h = L (g - 1) / (g^n - 1).
  EXPECT_NEAR(x[1] - x[0], 3.0 * (0.8 - 1.0) / (std::pow(0.8, 5) - 1.0), 1e-13);
  for (int i = 0; i + 2 <= 5; ++i) // ratios of differences of O(1) numbers: ~1e-15 each
    EXPECT_NEAR((x[i + 2] - x[i + 1]) / (x[i + 1] - x[i]), 0.8, 1e-12);
  for (int i = 5; i + 2 <= 9; ++i)
    EXPECT_NEAR((x[i + 2] - x[i + 1]) / (x[i + 1] - x[i]), 1.25, 1e-12);

  // The mesh uses exactly these coordinates.
  const Mesh m = make_rectangle(-1.0, 2.0, 5, 0.0, 1.0, 1, CellType::Quad4, "body", 0.8);
  std::set<double> xs;
  for (const auto& p : m.nodes)
    xs.insert(p[0]);
  const auto x1 = axis_coordinates({{-1.0, 2.0}, {5}, {0.8}});
  EXPECT_EQ(std::vector<double>(xs.begin(), xs.end()), x1);
}

TEST(BlockMesh, GradingCloseToOneStaysAccurate) {
  const auto x = axis_coordinates({{0.0, 1.0}, {10}, {1.0 + 1e-9}});
  for (int i = 0; i < 10; ++i) // (g^i - 1)/(g^n - 1) -> i/n as g -> 1, error O(g - 1)
    EXPECT_NEAR(x[i], i / 10.0, 1e-8);
}

TEST(BlockMesh, ConformingAndSidesCoverTheBoundary) {
  for (CellType type : kAllTypes) {
    BlockMeshSpec s = holed_spec(type);
    for (auto& r : s.block_regions)
      r = r.empty() ? "c" : r; // no hole: boundary = the box
    const Mesh m = make_block_mesh(s);
    const auto census = test::facet_census(m);
    std::size_t outer = 0;
    for (const auto& [key, count] : census) {
      EXPECT_TRUE(count == 1 || count == 2) << to_string(type);
      outer += count == 1;
    }
    const auto boundary = boundary_facets(m);
    EXPECT_EQ(boundary.size(), outer);
    // Each boundary facet is in exactly one side set.
    std::map<std::vector<Index>, int> in_sets;
    std::size_t total = 0;
    for (const auto& [name, facets] : m.facet_sets)
      for (const Facet& f : facets) {
        std::vector<Index> key(f.nodes.begin(), f.nodes.begin() + num_corners(f.type));
        std::sort(key.begin(), key.end());
        ++in_sets[key];
        ++total;
      }
    EXPECT_EQ(total, outer) << to_string(type);
    for (const Facet& f : boundary) {
      std::vector<Index> key(f.nodes.begin(), f.nodes.begin() + num_corners(f.type));
      std::sort(key.begin(), key.end());
      EXPECT_EQ(in_sets[key], 1) << to_string(type);
    }
    EXPECT_EQ(m.facet_sets.size(), cell_dim(type) == 2 ? 4u : 6u);
  }
}

TEST(BlockMesh, CellsArePositivelyOriented) {
  for (CellType type : kAllTypes) {
    const Mesh m = make_block_mesh(holed_spec(type));
    for (Index c = 0; c < m.num_cells(); ++c)
      ASSERT_TRUE(test::positively_oriented(m, c)) << to_string(type) << " cell " << c;
  }
}

// Triangle diagonal patterns: counts, area, orientation, conformity, and where the diagonals
// run (cell by cell on a 3 x 2 grid of unit squares).
TEST(BlockMesh, TriangleDiagonalPatterns) {
  const Diagonals all[] = {Diagonals::Right, Diagonals::Left, Diagonals::Alternating,
                           Diagonals::Crossed};
  for (CellType type : {CellType::Tri3, CellType::Tri6})
    for (Diagonals d : all) {
      if (d == Diagonals::Crossed && type == CellType::Tri6) continue;
      const std::string what = to_string(type) + " " + to_string(d);
      BlockMeshSpec s = holed_spec(type);
      s.diagonals = d;
      const Mesh m = make_block_mesh(s);
      // holed_spec: 2D blocks of 2x3, 3x3, hole, 3x2 cells = 21 quads.
      const Index quads = 21, per_quad = d == Diagonals::Crossed ? 4 : 2;
      EXPECT_EQ(m.num_cells(), per_quad * quads) << what;
      EXPECT_NEAR(total_measure(m), 7.0, 1e-12) << what; // as MeasureEqualsSumOfBlockMeasures
      for (Index c = 0; c < m.num_cells(); ++c)
        ASSERT_TRUE(test::positively_oriented(m, c)) << what << " cell " << c;
      for (const auto& [key, count] : test::facet_census(m))
        EXPECT_TRUE(count == 1 || count == 2) << what; // conforming
      EXPECT_NO_THROW(m.check_consistency()) << what;
    }

  // Which diagonal each quad of a 3 x 2 unit grid holds: the edge shared by its two
  // triangles, found as the pair of nodes both triangles of the quad use.
  auto diagonal_of = [](const Mesh& m, Index quad) {
    const Index* a = m.cell(2 * quad);
    const Index* b = m.cell(2 * quad + 1);
    std::vector<std::array<double, 3>> shared;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q)
        if (a[p] == b[q]) shared.push_back(m.nodes[a[p]]);
    EXPECT_EQ(shared.size(), 2u);
    // +1: lower-left to upper-right (slope > 0), −1: lower-right to upper-left.
    return (shared[1][0] - shared[0][0]) * (shared[1][1] - shared[0][1]) > 0 ? 1 : -1;
  };
  BlockMeshSpec s;
  s.x = {{0.0, 3.0}, {3}, {}};
  s.y = {{0.0, 2.0}, {2}, {}};
  s.cell = CellType::Tri3;
  s.block_regions = {"a"};
  for (Diagonals d : {Diagonals::Right, Diagonals::Left, Diagonals::Alternating}) {
    s.diagonals = d;
    const Mesh m = make_block_mesh(s);
    EXPECT_EQ(m.num_nodes(), 12);
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        const int expected = d == Diagonals::Right  ? 1
                             : d == Diagonals::Left ? -1
                                                    : ((i + j) % 2 == 0 ? 1 : -1);
        EXPECT_EQ(diagonal_of(m, i + 3 * j), expected) << to_string(d) << " " << i << "," << j;
      }
  }
  // Crossed: one more node per quad, at its centre, shared by its 4 triangles.
  s.diagonals = Diagonals::Crossed;
  const Mesh m = make_block_mesh(s);
  EXPECT_EQ(m.num_nodes(), 12 + 6);
  for (Index q = 0; q < 6; ++q) {
    const Index centre = m.cell(4 * q)[2];
    EXPECT_EQ(m.nodes[centre][0], 0.5 + q % 3) << q;
    EXPECT_EQ(m.nodes[centre][1], 0.5 + q / 3) << q;
    for (Index t = 1; t < 4; ++t)
      EXPECT_EQ(m.cell(4 * q + t)[2], centre);
  }
}

TEST(BlockMesh, QuadraticMidNodesAtEdgeMiddles) {
  for (CellType type : {CellType::Tri6, CellType::Quad8}) {
    const Mesh m = make_block_mesh(holed_spec(type));
    const int nc = num_corners(type);
    for (Index c = 0; c < m.num_cells(); ++c)
      for (int e = 0; e < nc; ++e) {
        const auto& a = m.nodes[m.cell(c)[e]];
        const auto& b = m.nodes[m.cell(c)[(e + 1) % nc]];
        const auto& mid = m.nodes[m.cell(c)[nc + e]];
        for (int k = 0; k < 2; ++k)
          EXPECT_EQ(mid[k], 0.5 * (a[k] + b[k])); // same formula
      }
  }
}

TEST(BlockMesh, SideSetsOutwardWithCellAndNodeSets) {
  const std::map<std::string, std::array<double, 3>> normals = {
      {"left", {-1, 0, 0}}, {"right", {1, 0, 0}}, {"bottom", {0, -1, 0}},
      {"top", {0, 1, 0}},   {"back", {0, 0, -1}}, {"front", {0, 0, 1}}};
  const std::map<std::string, std::pair<int, double>> planes = {
      {"left", {0, 0.0}}, {"right", {0, 3.0}}, {"bottom", {1, -1.0}},
      {"top", {1, 1.5}},  {"back", {2, 0.0}},  {"front", {2, 2.0}}};
  for (CellType type : kAllTypes) {
    const Mesh m = make_block_mesh(holed_spec(type));
    for (const auto& [name, facets] : m.facet_sets) {
      ASSERT_FALSE(facets.empty()) << name;
      for (const Facet& f : facets) {
        ASSERT_GE(f.cell, 0);
        const auto cn = test::cell_node_list(m, f.cell);
        for (Index n : f.nodes)
          EXPECT_NE(std::find(cn.begin(), cn.end(), n), cn.end());
        const auto n = facet_normal(m, f);
        for (int k = 0; k < 3; ++k) // axis-aligned facets: normal exact up to one rounding
          EXPECT_NEAR(n[k], normals.at(name)[k], 1e-15) << to_string(type) << " " << name;
      }
      // Node set = every node on the side's plane: the holes create no nodes, so even the
      // sides that a hole touches have nodes only where they have facets.
      std::vector<Index> expected;
      for (Index i = 0; i < m.num_nodes(); ++i)
        if (m.nodes[i][planes.at(name).first] == planes.at(name).second) expected.push_back(i);
      EXPECT_EQ(m.node_sets.at(name), expected) << to_string(type) << " " << name;
    }
  }
}

TEST(BlockMesh, RegionInterfaceFacetsBetweenTwoBlocks) {
  const int ny = 4, nz = 3;
  for (CellType type : kAllTypes) {
    BlockMeshSpec s;
    s.x = {{0.0, 1.0, 2.0}, {2, 3}, {}};
    s.y = {{0.0, 1.0}, {ny}, {}};
    s.z = {{0.0, 1.0}, {nz}, {}};
    s.cell = type;
    s.block_regions = {"a", "b"};
    const Mesh m = make_block_mesh(s);
    const auto facets = region_interface_facets(m, m.regions.at("a"), m.regions.at("b"));
    const std::size_t expected = type == CellType::Tet4   ? 2 * ny * nz
                                 : type == CellType::Hex8 ? ny * nz
                                                          : ny;
    EXPECT_EQ(facets.size(), expected) << to_string(type);
    double measure = 0.0;
    for (const Facet& f : facets) {
      EXPECT_EQ(m.cell_regions[f.cell], m.regions.at("a"));
      for (Index n : f.nodes)
        EXPECT_EQ(m.nodes[n][0], 1.0);
      EXPECT_NEAR(facet_normal(m, f)[0], 1.0, 1e-15);
      const auto& p = m.nodes[f.nodes[0]];
      const auto& q = m.nodes[f.nodes[1]];
      if (m.dim == 2) measure += std::abs(q[1] - p[1]);
    }
    if (m.dim == 2) {
      EXPECT_NEAR(measure, 1.0, 1e-15); // the interface is x = 1, 0 <= y <= 1
    }
  }
}

std::string error_of(const BlockMeshSpec& s) {
  try {
    make_block_mesh(s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BlockMesh, BadSpecsAreInputErrors) {
  BlockMeshSpec good;
  good.x = {{0.0, 1.0}, {2}, {1.0}};
  good.y = {{0.0, 1.0, 2.0}, {2, 2}, {}};
  good.cell = CellType::Quad4;
  good.block_regions = {"a", "b"};
  EXPECT_NO_THROW(make_block_mesh(good));

  BlockMeshSpec s = good;
  s.y.breaks = {0.0, 1.0, 1.0};
  EXPECT_EQ(error_of(s),
            "block mesh: y.breaks must be strictly increasing, but breaks[2] = 1 <= breaks[1] = 1");
  s = good;
  s.x.cells = {0};
  EXPECT_EQ(error_of(s), "block mesh: x.cells[0] = 0 must be at least 1");
  s = good;
  s.y.grading = {1.0, -0.5};
  EXPECT_EQ(error_of(s), "block mesh: y.grading[1] = -0.5 must be a finite number > 0");
  s = good;
  s.block_regions = {"a", "b", "c"};
  EXPECT_EQ(error_of(s), "block mesh: block_regions has 3 names, expected 2 (1 x 2 blocks, x "
                         "fastest)");
  s = good;
  s.block_regions = {"", ""};
  EXPECT_EQ(error_of(s), "block mesh: every block is a hole (all region names are empty)");
  s = good;
  s.cell = CellType::Line2;
  EXPECT_EQ(error_of(s), "block mesh: cell type line2 is not supported (tri3, tri6, quad4, "
                         "quad8, tet4, hex8)");
  s = good;
  s.diagonals = Diagonals::Left;
  EXPECT_EQ(error_of(s),
            "block mesh: diagonals 'left' applies to triangle cells (tri3, tri6), not to quad4");
  s.cell = CellType::Tri6;
  s.diagonals = Diagonals::Crossed;
  EXPECT_EQ(error_of(s), "block mesh: diagonals 'crossed' is available for tri3 cells only");
  // Every problem is reported at once.
  s = good;
  s.x.cells = {-1};
  s.y.grading = {0.0, 1.0};
  try {
    make_block_mesh(s);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.problems().size(), 2u);
  }
  EXPECT_THROW(make_rectangle(0, 1, 1, 0, 1, 1, CellType::Hex8), InputError);
  EXPECT_THROW(make_box(0, 1, 1, 0, 1, 1, 0, 1, 1, CellType::Quad4), InputError);
}

} // namespace
} // namespace bipot
