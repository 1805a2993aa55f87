// mesh_problems: non-finite coordinates, inverted or degenerate cells, coincident nodes that
// nothing joins and nodes of no cell, on meshes built in code.
#include "fem/input/mesh_checks.hpp"
#include "fem/mesh/structured_mesh.hpp"
#include "tests/unit/input/input_test_utils.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace bipot {
namespace {

using Pairs = std::vector<std::pair<Index, Index>>;

std::vector<std::string> problems(const Mesh& mesh, const Pairs& joined = {},
                                  Kinematics kin = Kinematics::PlaneStrain) {
  return mesh_problems(mesh, kin, joined, "in.yaml:3:9: mesh.file: m.msh");
}

// Two unit squares meshed apart: [0, 1] x [0, 1] (region a) and [1, 2] x [0, 1] (region b),
// their common edge's nodes there twice.
Mesh two_squares() {
  Mesh mesh = make_rectangle(0, 1, 1, 0, 1, 1, CellType::Quad4, "a");
  const Mesh b = make_rectangle(1, 2, 1, 0, 1, 1, CellType::Quad4, "b");
  const Index offset = mesh.num_nodes();
  mesh.nodes.insert(mesh.nodes.end(), b.nodes.begin(), b.nodes.end());
  const int region = mesh.region_id("b");
  for (Index c = 0; c < b.num_cells(); ++c) {
    std::vector<Index> ids(b.cell(c), b.cell(c) + b.cell_num_nodes(c));
    for (Index& id : ids)
      id += offset;
    mesh.add_cell(b.cell_types[c], ids, region);
  }
  return mesh;
}

// The node of `mesh` at (x, y).
Index node_at(const Mesh& mesh, double x, double y, Index after = -1) {
  for (Index n = after + 1; n < mesh.num_nodes(); ++n)
    if (mesh.nodes[n][0] == x && mesh.nodes[n][1] == y) return n;
  ADD_FAILURE() << "no node at (" << x << ", " << y << ")";
  return -1;
}

TEST(MeshChecks, SoundMeshesOfEveryCellType) {
  for (CellType t : {CellType::Tri3, CellType::Tri6, CellType::Quad4, CellType::Quad8}) {
    const Mesh mesh = make_rectangle(0, 2, 3, 0, 1, 2, t, "body", 1.5, 0.7);
    EXPECT_TRUE(problems(mesh).empty()) << to_string(t);
    // Corners on the axis (r = 0) are fine in axisymmetry: only det J is checked.
    EXPECT_TRUE(problems(mesh, {}, Kinematics::Axisymmetric).empty()) << to_string(t);
  }
  for (CellType t : {CellType::Tet4, CellType::Hex8})
    EXPECT_TRUE(problems(make_box(0, 1, 2, 0, 1, 2, 0, 3, 2, t), {}, Kinematics::ThreeD).empty())
        << to_string(t);
}

TEST(MeshChecks, CellInClockwiseOrder) {
  Mesh mesh = make_rectangle(0, 2, 2, 0, 1, 1, CellType::Quad4);
  std::reverse(mesh.cell_nodes.begin() + mesh.cell_offsets[1],
               mesh.cell_nodes.begin() + mesh.cell_offsets[2]);
  const auto p = problems(mesh);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], "in.yaml:3:9: mesh.file: m.msh: cell 1 (quad4, region 'body') is inverted or "
                  "degenerate: det J <= 0 at every corner and quadrature point (nodes in "
                  "clockwise order, or no area)");
}

TEST(MeshChecks, BowTieFoundAtItsCorners) {
  // Its corner polygon has zero signed area (the Gmsh reader's test passes it); det J changes
  // sign inside.
  Mesh mesh = make_rectangle(0, 2, 2, 0, 1, 1, CellType::Quad4);
  Index* c = mesh.cell_nodes.data() + mesh.cell_offsets[1];
  std::swap(c[2], c[3]);
  const auto p = problems(mesh);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(has(p, "cell 1 (quad4, region 'body') is inverted or degenerate: det J <= 0 at its "
                     "corner node "));
  EXPECT_TRUE(has(p, "corners and quadrature points)"));
}

TEST(MeshChecks, CollapsedAndInvertedCellsIn3DAndQuadratic) {
  Mesh box = make_box(0, 1, 1, 0, 1, 1, 0, 1, 1, CellType::Hex8);
  for (int a = 0; a < 4; ++a) // top face onto the bottom one: no volume
    box.nodes[box.cell(0)[4 + a]][2] = 0.0;
  EXPECT_TRUE(has(problems(box, {}, Kinematics::ThreeD),
                  "cell 0 (hex8, region 'body') is inverted or degenerate: det J <= 0 at every "
                  "corner and quadrature point (nodes in the wrong order, or no volume)"));
  // A Tri6 mid-node pulled across the opposite corner folds the cell.
  Mesh tri = make_rectangle(0, 1, 1, 0, 1, 1, CellType::Tri6);
  tri.nodes[tri.cell(0)[3]] = {0.5, 2.0, 0.0};
  EXPECT_TRUE(has(problems(tri), "cell 0 (tri6, region 'body') is inverted or degenerate"));
}

TEST(MeshChecks, NonFiniteCoordinates) {
  Mesh mesh = make_rectangle(0, 2, 2, 0, 1, 1, CellType::Quad4);
  mesh.nodes[1][0] = -std::numeric_limits<double>::quiet_NaN();
  mesh.nodes[4][1] = std::numeric_limits<double>::infinity();
  const auto p = problems(mesh);
  ASSERT_EQ(p.size(), 2u) << p[0];
  // Whatever its sign bit, a NaN reads "nan"; the cells using them are not also reported.
  EXPECT_EQ(p[0], "in.yaml:3:9: mesh.file: m.msh: node 1 at (nan, 0) has a coordinate that is "
                  "not a finite number");
  EXPECT_EQ(p[1], "in.yaml:3:9: mesh.file: m.msh: node 4 at (1, inf) has a coordinate that is "
                  "not a finite number");
}

TEST(MeshChecks, CoincidentNodesCrackTheBody) {
  const Mesh mesh = two_squares();
  const Index a0 = node_at(mesh, 1, 0), b0 = node_at(mesh, 1, 0, a0);
  const Index a1 = node_at(mesh, 1, 1), b1 = node_at(mesh, 1, 1, a1);
  const auto p = problems(mesh);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0], "in.yaml:3:9: mesh.file: m.msh: node " + std::to_string(a0) +
                      " at (1, 0) and node " + std::to_string(b0) +
                      " coincide, but no cell and no interface joins them (cell 0 uses the "
                      "one, cell 1 the other): the body is cracked there; merge the two nodes in "
                      "the mesh, or pair them by an interface with facet_sets if the bodies are "
                      "meant to be apart");
  // Paired by an interface, they are two bodies on purpose; one pair left is one crack.
  EXPECT_TRUE(problems(mesh, {{a0, b0}, {a1, b1}}).empty());
  EXPECT_EQ(problems(mesh, {{b1, a1}}).size(), 1u);
}

TEST(MeshChecks, ThreeCoincidentNodesTwoJoined) {
  // A third square's copy of (1, 0), joined to neither: one crack there, reported once.
  Mesh mesh = two_squares();
  const Index a0 = node_at(mesh, 1, 0), b0 = node_at(mesh, 1, 0, a0);
  const Index a1 = node_at(mesh, 1, 1), b1 = node_at(mesh, 1, 1, a1);
  mesh.nodes.push_back({1, 0, 0});
  mesh.nodes.push_back({1, -1, 0});
  mesh.nodes.push_back({0, -1, 0});
  const Index n = mesh.num_nodes();
  mesh.add_cell(CellType::Tri3, {n - 1, n - 2, n - 3}, 0);
  const auto p = problems(mesh, {{a0, b0}, {a1, b1}});
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(has(p, "and node " + std::to_string(n - 3) + " coincide"));
}

TEST(MeshChecks, NodesOfNoCellAndTheBound) {
  Mesh mesh = make_rectangle(0, 1, 1, 0, 1, 1, CellType::Quad4);
  mesh.nodes.push_back({0.5, 0.5, 0});
  auto p = problems(mesh);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], "in.yaml:3:9: mesh.file: m.msh: node 4 at (0.5, 0.5) belongs to no cell: "
                  "nothing gives its displacement a stiffness (the system to solve would be "
                  "singular)");
  // Ten of a kind are listed, then how many more.
  for (int i = 0; i < 14; ++i)
    mesh.nodes.push_back({0.5, 0.01 * i, 0});
  p = problems(mesh);
  ASSERT_EQ(p.size(), 11u);
  EXPECT_EQ(p[10], "in.yaml:3:9: mesh.file: m.msh: ... and 5 more nodes used by no cell");
}

} // namespace
} // namespace bipot
