#include "contact/interface/interface_mesh.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/cell_facets.hpp"
#include "interface_test_utils.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot::contact {
namespace {

using test::pi;
using test::pile_length;
using test::pile_radius;

/// Shaft and toe cell sizes of test::pile_mesh (m).
constexpr double shaft_h = 0.5, toe_h = pile_radius / 2;

class PileSplit : public ::testing::TestWithParam<CellType> {};

TEST_P(PileSplit, PlaneStrainPairsCellsWeightsNormals) {
  Mesh mesh = test::pile_mesh(GetParam());
  // A copy of "top" whose facets have lost their cell: side b must be decided by corners.
  mesh.facet_sets["top_orphans"] = mesh.facet_sets.at("top");
  for (Facet& f : mesh.facet_sets["top_orphans"])
    f.cell = -1;
  const Mesh before = mesh;
  const Index n0 = mesh.num_nodes();
  const auto on_interface = test::nodes_where(before, test::on_pile_interface);

  const auto ifaces = split_interfaces(mesh, Kinematics::PlaneStrain,
                                       {test::between("shaft", "pile", "soil")}, false);
  ASSERT_EQ(ifaces.size(), 1u);
  const Interface& iface = ifaces[0];
  EXPECT_EQ(iface.name, "shaft");
  EXPECT_NO_THROW(mesh.check_consistency());

  // One pair and one new node per original node on shaft + toe (counted geometrically).
  ASSERT_EQ(iface.pairs.size(), on_interface.size());
  EXPECT_EQ(mesh.num_nodes(), n0 + Index(on_interface.size()));
  for (const auto& p : iface.pairs) {
    EXPECT_LT(p.node_a, n0);
    EXPECT_GE(p.node_b, n0);
    EXPECT_EQ(mesh.nodes[p.node_a], mesh.nodes[p.node_b]);
    EXPECT_TRUE(std::binary_search(on_interface.begin(), on_interface.end(), p.node_a));
  }
  // Region-b cells use only copies on the interface, region-a cells never use a copy, and
  // every cell keeps its nodes' positions.
  const int pile = mesh.regions.at("pile");
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_num_nodes(c); ++k) {
      const Index id = mesh.cell(c)[k], old = before.cell(c)[k];
      EXPECT_EQ(mesh.nodes[id], before.nodes[old]);
      if (mesh.cell_regions[c] == pile)
        EXPECT_EQ(id, old);
      else
        EXPECT_EQ(id >= n0, test::on_pile_interface(before.nodes[old])) << "cell " << c;
    }

  // Straight facets: N_i integrates exactly, round-off only.
  EXPECT_NEAR(test::total_weight(iface), pile_length + pile_radius, 1e-12);
  const bool quadratic = cell_order(GetParam()) == 2;
  // Interior shaft node (a corner of the mesh lattice): h (linear) or 2 x h/6 (quadratic).
  const auto* mid_shaft = test::pair_at(mesh, iface, {pile_radius, -1.0, 0.0});
  ASSERT_NE(mid_shaft, nullptr);
  EXPECT_NEAR(mid_shaft->weight, quadratic ? shaft_h / 3 : shaft_h, 1e-14);
  if (quadratic) {
    const auto* mid_node = test::pair_at(mesh, iface, {pile_radius, -0.25, 0.0});
    ASSERT_NE(mid_node, nullptr);
    EXPECT_NEAR(mid_node->weight, 2 * shaft_h / 3, 1e-14);
  }

  // Normals: (1, 0) on the shaft, (0, -1) on the toe, exact (axis-aligned facets); tangents
  // (-n_y, n_x). At the corner the weights are h/2 (or h/6) from each side, so the average is
  // (h_shaft, -h_toe)/|.|: between the two, pointing out of the pile.
  const double nc = std::hypot(shaft_h, toe_h);
  for (const auto& p : iface.pairs) {
    const auto& x = mesh.nodes[p.node_a];
    std::array<double, 3> n;
    if (x[0] == pile_radius && x[1] == -pile_length)
      n = {shaft_h / nc, -toe_h / nc, 0};
    else if (x[0] == pile_radius)
      n = {1, 0, 0};
    else
      n = {0, -1, 0};
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(p.normal[d], n[d], 1e-14) << "node at " << x[0] << ", " << x[1];
    EXPECT_NEAR(p.tangent1[0], -n[1], 1e-14);
    EXPECT_NEAR(p.tangent1[1], n[0], 1e-14);
    EXPECT_EQ(p.tangent2, (std::array<double, 3>{0, 0, 0}));
  }
  const auto* corner = test::pair_at(mesh, iface, {pile_radius, -pile_length, 0.0});
  ASSERT_NE(corner, nullptr);
  EXPECT_GT(corner->normal[0], 0.0);
  EXPECT_LT(corner->normal[1], 0.0);

  // Body-1 facets: the pile's side (original ids), outward of the pile cells.
  ASSERT_EQ(iface.facets_a.size(),
            quadratic ? (on_interface.size() - 1) / 2 : on_interface.size() - 1);
  for (const Facet& f : iface.facets_a) {
    EXPECT_EQ(mesh.cell_regions[f.cell], pile);
    for (Index v : f.nodes)
      EXPECT_LT(v, n0);
  }

  // Sets at the shaft's top node: soil facets use the copy, pile facets the original; the
  // node sets hold both. Facets without a cell follow the region holding all their corners.
  const auto* top_pair = test::pair_at(mesh, iface, {pile_radius, 0.0, 0.0});
  ASSERT_NE(top_pair, nullptr);
  const Index top_a = top_pair->node_a, top_b = top_pair->node_b;
  for (const char* set : {"top", "top_orphans"}) {
    int soil_hits = 0, pile_hits = 0;
    for (std::size_t i = 0; i < mesh.facet_sets.at(set).size(); ++i) {
      const Facet& f = mesh.facet_sets.at(set)[i];
      const Facet& old = before.facet_sets.at(set)[i];
      const bool pile_side = before.cell_regions[before.facet_sets.at("top")[i].cell] == pile;
      const bool touches = std::count(old.nodes.begin(), old.nodes.end(), top_a) > 0;
      if (!touches) {
        EXPECT_EQ(f.nodes, old.nodes);
        continue;
      }
      const Index expect = pile_side ? top_a : top_b;
      EXPECT_EQ(std::count(f.nodes.begin(), f.nodes.end(), expect), 1) << set;
      (pile_side ? pile_hits : soil_hits)++;
    }
    EXPECT_EQ(pile_hits, 1) << set;
    EXPECT_EQ(soil_hits, 1) << set;
  }
  const auto& top = mesh.node_sets.at("top");
  EXPECT_TRUE(std::binary_search(top.begin(), top.end(), top_a));
  EXPECT_TRUE(std::binary_search(top.begin(), top.end(), top_b));
  EXPECT_TRUE(std::is_sorted(top.begin(), top.end()));
  EXPECT_EQ(top.size(), before.node_sets.at("top").size() + 1);
  // "left" (x = 0) holds the toe's axis node, so it gains that copy; "right" is untouched.
  EXPECT_EQ(mesh.node_sets.at("left").size(), before.node_sets.at("left").size() + 1);
  EXPECT_EQ(mesh.node_sets.at("right"), before.node_sets.at("right"));
}

TEST_P(PileSplit, AxisymmetricWeightsArePappus) {
  Mesh mesh = test::pile_mesh(GetParam());
  const auto ifaces = split_interfaces(mesh, Kinematics::Axisymmetric,
                                       {test::between("shaft", "pile", "soil")}, false);
  // Shaft: cylinder 2π R L; toe: disc π R². N_i 2πr is a polynomial on straight facets and the
  // rule has degree 2p + 1, so the sum is exact up to round-off.
  EXPECT_NEAR(test::total_weight(ifaces[0]),
              2 * pi * pile_radius * pile_length + pi * pile_radius * pile_radius, 1e-12);
  // The node on the axis, toe element length h: ∫_0^h (1 − r/h) 2πr dr = π h²/3 for Line2;
  // for Line3 N_0 = (1 − s)(1 − 2s), s = r/h, and 2πh² ∫_0^1 s(1 − s)(1 − 2s) ds = 0. Its
  // normal then comes from the plain facet average: the toe's (0, −1).
  const auto* axis = test::pair_at(mesh, ifaces[0], {0.0, -pile_length, 0.0});
  ASSERT_NE(axis, nullptr);
  if (cell_order(GetParam()) == 1)
    EXPECT_NEAR(axis->weight, pi * toe_h * toe_h / 3, 1e-14);
  else
    EXPECT_NEAR(axis->weight, 0.0, 1e-14);
  EXPECT_NEAR(axis->normal[0], 0.0, 1e-15);
  EXPECT_NEAR(axis->normal[1], -1.0, 1e-15);
}

TEST_P(PileSplit, TieOnlyKeepsNodesAndWeights) {
  Mesh split = test::pile_mesh(GetParam());
  Mesh tied = split;
  const Mesh before = tied;
  const auto a = split_interfaces(split, Kinematics::Axisymmetric,
                                  {test::between("shaft", "pile", "soil")}, false);
  const auto b = split_interfaces(tied, Kinematics::Axisymmetric,
                                  {test::between("shaft", "pile", "soil")}, true);
  EXPECT_EQ(tied.num_nodes(), before.num_nodes());
  EXPECT_EQ(tied.cell_nodes, before.cell_nodes);
  EXPECT_EQ(tied.node_sets, before.node_sets);
  ASSERT_EQ(a[0].pairs.size(), b[0].pairs.size());
  for (std::size_t i = 0; i < b[0].pairs.size(); ++i) {
    EXPECT_EQ(b[0].pairs[i].node_a, b[0].pairs[i].node_b);
    EXPECT_EQ(b[0].pairs[i].node_a, a[0].pairs[i].node_a);
    // Same facets, same arithmetic: identical.
    EXPECT_EQ(b[0].pairs[i].weight, a[0].pairs[i].weight);
    EXPECT_EQ(b[0].pairs[i].normal, a[0].pairs[i].normal);
  }
}

INSTANTIATE_TEST_SUITE_P(CellTypes, PileSplit,
                         ::testing::Values(CellType::Quad4, CellType::Tri3, CellType::Quad8,
                                           CellType::Tri6),
                         [](const auto& info) { return to_string(info.param); });

} // namespace
} // namespace bipot::contact
