// Facet sets paired along the normals of side a (Pairing::Normal): a flat body below a body
// whose bottom is a parabola, apart before contact.
#include "contact/interface/coincident_nodes.hpp"
#include "contact/interface/interface_mesh.hpp"

#include "fem/core/error.hpp"
#include "interface_test_utils.hpp"

#include <gtest/gtest.h>

namespace bipot::contact {
namespace {

constexpr double lift = 0.1;      ///< m, height of the upper body's lowest point above y = 0
constexpr double curvature = 0.5; ///< 1/m: the upper body's bottom is y = lift + curvature x²

/// "flat" = [0, 1] x [-1, 0] with nx x 2 cells and facet set "flat_top"; "cap" = nx_cap x 2
/// cells over [0, 1] whose bottom is y = lift + curvature x² (top at y = 1), facet set
/// "cap_bottom". No node is shared.
Mesh flat_and_cap(int nx, int nx_cap) {
  Mesh m = make_rectangle(0, 1, nx, -1, 0, 2, CellType::Quad4, "flat");
  m.facet_sets["flat_top"] = m.facet_sets.at("top");
  const Mesh cap = make_rectangle(0, 1, nx_cap, 0, 1, 2, CellType::Quad4, "cap");
  const Index offset = m.num_nodes(), cell_offset = m.num_cells();
  for (auto x : cap.nodes) {
    x[1] += (lift + curvature * x[0] * x[0]) * (1 - x[1]); // bottom on the parabola
    m.nodes.push_back(x);
  }
  for (Index c = 0; c < cap.num_cells(); ++c) {
    std::vector<Index> ids(cap.cell(c), cap.cell(c) + cap.cell_num_nodes(c));
    for (Index& v : ids)
      v += offset;
    m.add_cell(cap.cell_types[c], ids, m.region_id("cap"));
  }
  for (Facet f : cap.facet_sets.at("bottom")) {
    for (Index& v : f.nodes)
      v += offset;
    f.cell += cell_offset;
    m.facet_sets["cap_bottom"].push_back(f);
  }
  return m;
}

InterfaceDefinition along_normals(const std::string& a, const std::string& b) {
  InterfaceDefinition d;
  d.name = "indent";
  d.facet_set_a = a;
  d.facet_set_b = b;
  d.pairing = Pairing::Normal;
  return d;
}

TEST(NormalPairing, PairsTheNodeAboveWithItsDistanceAsGap) {
  Mesh mesh = flat_and_cap(4, 4);
  const Mesh before = mesh;
  const auto ifaces = split_interfaces(mesh, Kinematics::PlaneStrain,
                                       {along_normals("flat_top", "cap_bottom")}, false);
  EXPECT_EQ(mesh.nodes, before.nodes); // nothing split or moved
  const Interface& iface = ifaces[0];
  ASSERT_EQ(iface.pairs.size(), 5u);
  for (const auto& p : iface.pairs) {
    const auto& xa = mesh.nodes[p.node_a];
    const auto& xb = mesh.nodes[p.node_b];
    EXPECT_EQ(xa[1], 0.0);
    // The partner is straight above (same x from the same generator) at the parabola.
    EXPECT_EQ(xb[0], xa[0]);
    EXPECT_EQ(p.normal, (std::array<double, 3>{0, 1, 0}));
    EXPECT_NEAR(p.gap, lift + curvature * xa[0] * xa[0], 1e-15);
  }
  EXPECT_NEAR(test::total_weight(iface), 1.0, 1e-14); // the flat's length
}

TEST(NormalPairing, CurvedSideAIsRejectedItsNormalsMissTheFlatNodes) {
  // The parabola's node normals lean outward: even at x = 0 the only facet, the chord to
  // (0.25, 0.13125), gives n ∝ (0.03125, -0.25), whose line through (0, 0.1) passes
  // 0.1 × 0.03125 / |(0.03125, 0.25)| = 0.0124 m from the flat node (0, 0).
  Mesh mesh = flat_and_cap(4, 4);
  const Mesh before = mesh;
  const std::string msg = test::message_of([&] {
    split_interfaces(mesh, Kinematics::PlaneStrain, {along_normals("cap_bottom", "flat_top")},
                     false);
  });
  EXPECT_NE(msg.find("interface 'indent': facet sets 'cap_bottom' and 'flat_top' do not face "
                     "each other node by node along the normals of 'cap_bottom' (within "
                     "2.24e-06 m of the line); 5 of 5 nodes of 'cap_bottom' have no node of "
                     "'flat_top' on their normal, first: node 15 at (0, 0.1) (nearest node of "
                     "'flat_top' 0.0124 m off the line), node 16 "),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("; 5 of 5 nodes of 'flat_top' are no node's partner, first: node 10 at (0, "
                     "0), node 11"),
            std::string::npos)
      << msg;
  EXPECT_EQ(mesh.nodes, before.nodes);
}

TEST(NormalPairing, DifferentNodeCountsAreRejected) {
  // 4 flat cells, 8 cap cells: every flat node finds a cap node above it, but the cap's odd
  // nodes are nobody's partner.
  Mesh mesh = flat_and_cap(4, 8);
  const std::string msg = test::message_of([&] {
    split_interfaces(mesh, Kinematics::PlaneStrain, {along_normals("flat_top", "cap_bottom")},
                     false);
  });
  EXPECT_EQ(msg.find("have no node of"), std::string::npos) << msg;
  EXPECT_NE(msg.find("4 of 9 nodes of 'cap_bottom' are no node's partner, first: node "),
            std::string::npos)
      << msg;
}

TEST(NormalPairing, NearestAlongTheLineWinsAndGapIsSigned) {
  // Node 0 at the origin with normal +y; on its line: b nodes at y = 2, y = -0.5 (behind) and
  // one 1e-3 off the line at y = 0.1. The nearest on the line (|s| = 0.5, behind) wins.
  Mesh mesh;
  mesh.dim = 2;
  mesh.nodes = {{0, 0, 0}, {0, 2, 0}, {0, -0.5, 0}, {1e-3, 0.1, 0}};
  const auto partners = match_nodes_along_normals(mesh, {0}, {{0, 1, 0}}, {1, 2, 3}, 1e-6);
  ASSERT_EQ(partners.size(), 1u);
  EXPECT_EQ(partners[0].node, 2);
  EXPECT_EQ(partners[0].gap, -0.5);
  EXPECT_EQ(partners[0].off_line, 0.0);
  // Without the nodes on the line: none, and the miss distance of the nearest.
  const auto none = match_nodes_along_normals(mesh, {0}, {{0, 1, 0}}, {3}, 1e-6);
  EXPECT_EQ(none[0].node, -1);
  EXPECT_DOUBLE_EQ(none[0].off_line, 1e-3);
}

} // namespace
} // namespace bipot::contact
