#include "contact/interface/interface_frame.hpp"
#include "contact/interface/interface_mesh.hpp"

#include "interface_test_utils.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot::contact {
namespace {

std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

class BoxSplit : public ::testing::TestWithParam<CellType> {};

TEST_P(BoxSplit, TwoRegionsShareTheFaceX1) {
  // [0, 2] x [0, 1] x [0, 1.5], split at x = 1 into "left_part" and "right_part"; the
  // interface is the 1 x 1.5 face x = 1, with 3 x 3 lattice nodes.
  BlockMeshSpec spec;
  spec.x = {{0, 1, 2}, {2, 2}, {}};
  spec.y = {{0, 1}, {2}, {}};
  spec.z = {{0, 1.5}, {2}, {}};
  spec.cell = GetParam();
  spec.block_regions = {"left_part", "right_part"};
  Mesh mesh = make_block_mesh(spec);
  const Index n0 = mesh.num_nodes();
  const auto ifaces = split_interfaces(mesh, Kinematics::ThreeD,
                                       {test::between("mid", "left_part", "right_part")}, false);
  EXPECT_NO_THROW(mesh.check_consistency());
  const Interface& iface = ifaces[0];
  ASSERT_EQ(iface.pairs.size(), 9u);
  EXPECT_EQ(mesh.num_nodes(), n0 + 9);
  // Planar faces: N_i integrates exactly, round-off only.
  EXPECT_NEAR(test::total_weight(iface), 1.5, 1e-14);
  for (const auto& p : iface.pairs) {
    EXPECT_EQ(mesh.nodes[p.node_a][0], 1.0);
    EXPECT_EQ(mesh.nodes[p.node_a], mesh.nodes[p.node_b]);
    EXPECT_NE(p.node_a, p.node_b);
    // Out of the left part: +x; frame from complete_frame: e_y, then n x e_y = e_z.
    const std::array<double, 3> n{1, 0, 0}, t1{0, 1, 0}, t2{0, 0, 1};
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(p.normal[d], n[d], 1e-15);
      EXPECT_NEAR(p.tangent1[d], t1[d], 1e-15);
      EXPECT_NEAR(p.tangent2[d], t2[d], 1e-15);
    }
  }
  if (GetParam() == CellType::Hex8) {
    // Bilinear quads of 0.5 x 0.75: a node gets a quarter of each adjacent face.
    const auto* centre = test::pair_at(mesh, iface, {1.0, 0.5, 0.75});
    const auto* corner = test::pair_at(mesh, iface, {1.0, 0.0, 0.0});
    ASSERT_TRUE(centre && corner);
    EXPECT_NEAR(centre->weight, 0.375, 1e-15);
    EXPECT_NEAR(corner->weight, 0.09375, 1e-15);
  }
}

INSTANTIATE_TEST_SUITE_P(CellTypes, BoxSplit, ::testing::Values(CellType::Hex8, CellType::Tet4),
                         [](const auto& info) { return to_string(info.param); });

TEST(LayeredSoil, LayersShareOneCopyAtTheirJunction) {
  // Pile [0, 0.135] x [-2, 0] in "upper" soil (y > -1) and "lower" soil (y < -1).
  BlockMeshSpec spec;
  spec.x = {{0, 0.135, 2}, {1, 2}, {}};
  spec.y = {{-3, -2, -1, 0}, {1, 2, 2}, {}};
  spec.block_regions = {"lower", "lower", "pile", "lower", "pile", "upper"};
  Mesh mesh = make_block_mesh(spec);
  const Index n0 = mesh.num_nodes();
  const auto ifaces = split_interfaces(
      mesh, Kinematics::PlaneStrain,
      {test::between("upper", "pile", "upper"), test::between("lower", "pile", "lower")}, false);
  EXPECT_NO_THROW(mesh.check_consistency());
  // Upper shaft 1 m (3 nodes); lower shaft 1 m + toe 0.135 m (3 + 2 nodes, one shared by
  // both). The junction node (0.135, -1) is in both but is copied once: 6 distinct positions.
  EXPECT_EQ(ifaces[0].pairs.size(), 3u);
  EXPECT_EQ(ifaces[1].pairs.size(), 4u);
  EXPECT_EQ(mesh.num_nodes(), n0 + 6);
  EXPECT_NEAR(test::total_weight(ifaces[0]), 1.0, 1e-14);
  EXPECT_NEAR(test::total_weight(ifaces[1]), 1.135, 1e-14);
  const auto* up = test::pair_at(mesh, ifaces[0], {0.135, -1, 0});
  const auto* low = test::pair_at(mesh, ifaces[1], {0.135, -1, 0});
  ASSERT_TRUE(up && low);
  EXPECT_EQ(up->node_a, low->node_a);
  EXPECT_EQ(up->node_b, low->node_b);
  // Both layers use that copy: they stay connected to each other, not to the pile.
  const int pile = mesh.regions.at("pile");
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_num_nodes(c); ++k)
      if (mesh.cell(c)[k] == up->node_a || mesh.cell(c)[k] == up->node_b) {
        EXPECT_EQ(mesh.cell(c)[k] == up->node_a, mesh.cell_regions[c] == pile) << "cell " << c;
      }
  // Each interface's weight at the junction is its own half-facet: 0.5 m on each side.
  EXPECT_NEAR(up->weight, 0.25, 1e-15);
  EXPECT_NEAR(low->weight, 0.25, 1e-15);
}

TEST(LayeredSoil, LaterInterfaceRenumbersEarlierPairs) {
  // "rock" is body 1 against the pile, after the pile was body 1 against the soil: the pile
  // cells move to copies, and the first interface's node_a must follow them.
  BlockMeshSpec spec;
  spec.x = {{0, 1, 2}, {1, 1}, {}};
  spec.y = {{0, 1, 2}, {1, 1}, {}};
  spec.block_regions = {"rock", "soil", "pile", "soil"};
  Mesh mesh = make_block_mesh(spec);
  const auto ifaces = split_interfaces(
      mesh, Kinematics::PlaneStrain,
      {test::between("ps", "pile", "soil"), test::between("rp", "rock", "pile")}, false);
  EXPECT_NO_THROW(mesh.check_consistency());
  const int pile = mesh.regions.at("pile");
  for (const auto& p : ifaces[0].pairs) {
    // node_a of "ps" is used by pile cells, node_b by no pile cell.
    bool a_in_pile = false, b_in_pile = false;
    for (Index c = 0; c < mesh.num_cells(); ++c)
      if (mesh.cell_regions[c] == pile)
        for (int k = 0; k < mesh.cell_num_nodes(c); ++k) {
          a_in_pile = a_in_pile || mesh.cell(c)[k] == p.node_a;
          b_in_pile = b_in_pile || mesh.cell(c)[k] == p.node_b;
        }
    EXPECT_TRUE(a_in_pile);
    EXPECT_FALSE(b_in_pile);
  }
  for (const Facet& f : ifaces[0].facets_a)
    for (Index v : f.nodes)
      EXPECT_NE(std::find(mesh.cell(f.cell), mesh.cell(f.cell) + 4, v), mesh.cell(f.cell) + 4);
}

TEST(InterfaceFrame, CompleteFrameIsOrthonormalAndRightHanded) {
  const double s = 1 / std::sqrt(14.0);
  for (const std::array<double, 3>& n :
       {std::array<double, 3>{s, 2 * s, 3 * s}, {-3 * s, s, -2 * s}, {0, 0, -1}, {0, 1, 0}}) {
    std::array<double, 3> t1, t2;
    complete_frame(n, 3, t1, t2);
    const auto c = cross(t1, t2);
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(c[d], n[d], 1e-15); // t1 x t2 = n, round-off
    double nt1 = 0, nt2 = 0, t11 = 0;
    for (int d = 0; d < 3; ++d) {
      nt1 += n[d] * t1[d];
      nt2 += n[d] * t2[d];
      t11 += t1[d] * t1[d];
    }
    EXPECT_NEAR(nt1, 0, 1e-15);
    EXPECT_NEAR(nt2, 0, 1e-15);
    EXPECT_NEAR(t11, 1, 1e-15);
  }
  // 2D: n rotated by +90 degrees; n x t = +1.
  std::array<double, 3> t1, t2;
  complete_frame({0.6, -0.8, 0}, 2, t1, t2);
  EXPECT_EQ(t1, (std::array<double, 3>{0.8, 0.6, 0}));
  EXPECT_EQ(t2, (std::array<double, 3>{0, 0, 0}));
}

TEST(InterfaceFrame, ToLocalAndBack) {
  InterfacePair p;
  p.normal = {0.6, -0.8, 0};
  complete_frame(p.normal, 2, p.tangent1, p.tangent2); // t1 = (0.8, 0.6)
  const double v[2] = {1.0, 2.0};
  const LocalVector l = to_local(p, v, 2);
  ASSERT_EQ(l.size(), 2);
  EXPECT_NEAR(l(0), 0.6 - 1.6, 1e-15); // n·v
  EXPECT_NEAR(l(1), 0.8 + 1.2, 1e-15); // t·v
  double back[2];
  to_global(p, l, back, 2);
  EXPECT_NEAR(back[0], 1.0, 1e-15);
  EXPECT_NEAR(back[1], 2.0, 1e-15);

  const double s = 1 / std::sqrt(3.0);
  p.normal = {s, -s, s};
  complete_frame(p.normal, 3, p.tangent1, p.tangent2);
  const double w[3] = {0.3, -1.7, 2.9};
  const LocalVector m = to_local(p, w, 3);
  EXPECT_NEAR(m(0), s * (0.3 + 1.7 + 2.9), 1e-14);
  // Orthonormal frame: the length is kept and the inverse is the transpose.
  EXPECT_NEAR(m.norm(), std::sqrt(0.09 + 2.89 + 8.41), 1e-14);
  double back3[3];
  to_global(p, m, back3, 3);
  // Two 3-term dot products of values up to 3 (and 1/sqrt(3) round-off in the frame): a few
  // ulps of 3.
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(back3[d], w[d], 1e-14);
}

} // namespace
} // namespace bipot::contact
