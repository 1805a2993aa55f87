// free_rigid_body_modes: which rigid motions each stage leaves free, per body, in plane
// strain, axisymmetry and 3D, and the conservative rule for bodies held by an interface.
#include "fem/input/rigid_body_checks.hpp"
#include "fem/mesh/structured_mesh.hpp"
#include "tests/unit/input/input_test_utils.hpp"

#include <gtest/gtest.h>

namespace bipot {
namespace {

DirichletSpec fix(const std::string& set, int component) {
  DirichletSpec d;
  d.set = set;
  d.component = component;
  return d;
}

// One stage per entry, "s0", "s1", ..., stage s at "in.yaml:<10 + s>:5: stages[s]".
ProblemSpec problem(const std::string& kinematics,
                    const std::vector<std::vector<DirichletSpec>>& stages) {
  ProblemSpec spec;
  spec.file = "in.yaml";
  spec.kinematics = kinematics;
  for (std::size_t s = 0; s < stages.size(); ++s) {
    StageSpec st;
    st.name = "s" + std::to_string(s);
    st.where = "in.yaml:" + std::to_string(10 + s) + ":5: stages[" + std::to_string(s) + "]";
    st.boundary_conditions = stages[s];
    spec.stages.push_back(st);
  }
  return spec;
}

// A node set of the nodes of `mesh` where `pred(x)` holds.
template <class Pred> void add_set(Mesh& mesh, const std::string& name, Pred pred) {
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    if (pred(mesh.nodes[n])) mesh.node_sets[name].push_back(n);
}

std::vector<std::string> free_modes(const ProblemSpec& spec, const Mesh& mesh,
                                    const std::vector<OpeningInterface>& interfaces = {}) {
  return free_rigid_body_modes(spec, mesh, interfaces);
}

const std::string kStop = "; add boundary conditions that stop ";

TEST(RigidBodyChecks, PlaneStrain) {
  Mesh mesh = make_rectangle(0, 1, 2, 0, 1, 2, CellType::Quad4);
  add_set(mesh, "corner", [](const auto& x) { return x[0] == 1 && x[1] == 0; });
  const auto p = free_modes(problem("plane_strain", {{},
                                                     {fix("left", 0)},
                                                     {fix("corner", 0), fix("corner", 1)},
                                                     {fix("corner", 0)},
                                                     {fix("bottom", 0), fix("bottom", 1)},
                                                     {fix("left", 0), fix("bottom", 1)}}),
                            mesh);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p[0], "in.yaml:10:5: stages[0]: stage 's0': the body of region 'body' (cells 0-3): "
                  "free translations along x and y, and rotation" +
                      kStop + "them");
  // The left side's nodes lie at different heights: held along x, it cannot turn either.
  EXPECT_EQ(p[1], "in.yaml:11:5: stages[1]: stage 's1': the body of region 'body' (cells 0-3): "
                  "free translation along y" +
                      kStop + "it");
  EXPECT_TRUE(has({p[2]}, "stage 's2': the body of region 'body' (cells 0-3): free rotation "
                          "about (1, 0)" +
                              kStop + "it"));
  EXPECT_TRUE(has({p[3]}, "stage 's3': the body of region 'body' (cells 0-3): free translation "
                          "along y and rotation" +
                              kStop + "them"));
}

TEST(RigidBodyChecks, AxisymmetryHasOnlyTheAxialTranslation) {
  const Mesh mesh = make_rectangle(0, 1, 2, 0, 1, 2, CellType::Quad8);
  const auto p = free_modes(
      problem("axisymmetric", {{fix("left", 0), fix("right", 0)}, {fix("bottom", 1)}}), mesh);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(has(p, "stage 's0': the body of region 'body' (cells 0-3): free translation along "
                     "z" +
                         kStop + "it"));
}

TEST(RigidBodyChecks, ThreeD) {
  Mesh mesh = make_box(0, 1, 2, 0, 1, 2, 0, 2, 2, CellType::Hex8);
  add_set(mesh, "corner", [](const auto& x) { return x[0] == 1 && x[1] == 0 && x[2] == 0; });
  add_set(mesh, "edge", [](const auto& x) { return x[0] == 0 && x[1] == 0; });
  const auto p =
      free_modes(problem("three_d", {{},
                                     {fix("corner", 0), fix("corner", 1), fix("corner", 2)},
                                     {fix("edge", 0), fix("edge", 1)},
                                     {fix("back", 2)},
                                     {fix("back", 0), fix("back", 1), fix("back", 2)}}),
                 mesh);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_TRUE(has({p[0]}, "stage 's0': the body of region 'body' (cells 0-7): free translations "
                          "along x, y and z, and rotations about x, y and z"));
  EXPECT_TRUE(has({p[1]}, "stage 's1': the body of region 'body' (cells 0-7): free rotations "
                          "about x, y and z"));
  EXPECT_TRUE(has({p[2]}, "stage 's2': the body of region 'body' (cells 0-7): free translation "
                          "along z and rotation about the axis along z through (0, 0, 1)"));
  EXPECT_TRUE(has({p[3]}, "stage 's3': the body of region 'body' (cells 0-7): free translations "
                          "along x and y, and rotation about z"));
}

TEST(RigidBodyChecks, EachBodyOnItsOwn) {
  // Two blocks apart (a hole between them): holding the left one holds nothing of the right.
  BlockMeshSpec spec;
  spec.x = {{0, 1, 2, 3}, {1, 1, 2}, {}};
  spec.y = {{0, 1}, {2}, {}};
  spec.block_regions = {"a", "", "b"};
  const Mesh mesh = make_block_mesh(spec);
  const auto p = free_modes(problem("plane_strain", {{fix("left", 0), fix("left", 1)},
                                                     {fix("right", 0), fix("right", 1)}}),
                            mesh);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_TRUE(has({p[0]}, "stage 's0': the body of region 'b' (cells 1-2, 4-5): free "
                          "translations"));
  EXPECT_TRUE(has({p[1]}, "stage 's1': the body of region 'a' (cells 0, 3): free translations"));
}

// Two unit squares side by side (regions a and b), their common edge's nodes paired by an
// interface that can open; "left" holds a, "b_right" is b's right side (nodes and facets).
struct TwoBodies {
  Mesh mesh;
  OpeningInterface joint;
  TwoBodies() {
    BlockMeshSpec spec;
    spec.x = {{0, 1, 2}, {1, 1}, {}};
    spec.y = {{0, 1}, {1}, {}};
    spec.block_regions = {"a", "b"};
    mesh = make_block_mesh(spec);
    // Split along x = 1: b's cell gets copies of the shared nodes.
    joint.name = "joint";
    Index* cell_b = mesh.cell_nodes.data() + mesh.cell_offsets[1];
    for (int k = 0; k < 4; ++k)
      if (mesh.nodes[cell_b[k]][0] == 1) {
        mesh.nodes.push_back(mesh.nodes[cell_b[k]]);
        joint.pairs.emplace_back(cell_b[k], mesh.num_nodes() - 1);
        cell_b[k] = mesh.num_nodes() - 1;
      }
    mesh.node_sets["b_right"] = mesh.node_sets["right"];
    mesh.facet_sets["b_right"] = mesh.facet_sets["right"];
  }
};

TEST(RigidBodyChecks, BodyHangingOnAnInterfaceThatCanOpen) {
  TwoBodies t;
  const std::vector<DirichletSpec> hold_a = {fix("left", 0), fix("left", 1)};
  ProblemSpec spec = problem("plane_strain", {hold_a});
  auto p = free_modes(spec, t.mesh, {t.joint});
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], "in.yaml:10:5: stages[0]: stage 's0': the body of region 'b' (cell 1) hangs "
                  "only on interface 'joint', which can open, and no gravity, load, initial "
                  "stress or interference presses it on: free translations along x and y, and "
                  "rotation" +
                      kStop + "them");
  // Without the interface's pairs it is just a free body.
  EXPECT_TRUE(has(free_modes(spec, t.mesh), "(cell 1): free translations along x and y"));

  // Conservative: any condition of its own, or anything that may press it on, may hold it.
  EXPECT_TRUE(
      free_modes(problem("plane_strain", {{fix("left", 0), fix("left", 1), fix("b_right", 0)}}),
                 t.mesh, {t.joint})
          .empty());
  LoadSpec gravity;
  gravity.type = LoadSpec::Type::Gravity;
  LoadSpec push;
  push.set = "b_right";
  push.pressure = 10;
  for (const LoadSpec& load : {gravity, push}) {
    ProblemSpec loaded = spec;
    loaded.stages[0].loads = {load};
    EXPECT_TRUE(free_modes(loaded, t.mesh, {t.joint}).empty());
  }
  ProblemSpec stressed = spec;
  stressed.initial_stress.push_back({"b", "constant", 0, 1, 0, {-1, -1, -1, 0}, ""});
  EXPECT_TRUE(free_modes(stressed, t.mesh, {t.joint}).empty());
  OpeningInterface overlapping = t.joint;
  overlapping.smallest_gap = -1e-4;
  EXPECT_TRUE(free_modes(spec, t.mesh, {overlapping}).empty());

  // An interference prescribed by a stage is kept by the next ones until one changes it.
  ProblemSpec installed = problem("plane_strain", {hold_a, hold_a, hold_a});
  installed.stages[0].interface_gaps = {{"joint", -1e-4, ""}};
  installed.stages[2].interface_gaps = {{"joint", 0.0, ""}};
  p = free_modes(installed, t.mesh, {t.joint});
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(has(p, "stage 's2': the body of region 'b' (cell 1) hangs only on interface "
                     "'joint'"));
}

TEST(RigidBodyChecks, ListIsBounded) {
  const Mesh mesh = make_rectangle(0, 1, 1, 0, 1, 1, CellType::Tri3);
  const auto p =
      free_modes(problem("plane_strain", std::vector<std::vector<DirichletSpec>>(12)), mesh);
  ASSERT_EQ(p.size(), 11u);
  EXPECT_TRUE(has({p[9]}, "stage 's9'"));
  EXPECT_EQ(p[10], "in.yaml: ... and 2 more bodies free to move");
}

} // namespace
} // namespace bipot
