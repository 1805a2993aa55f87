#include "contact/interface/coincident_nodes.hpp"
#include "contact/interface/interface_mesh.hpp"

#include "fem/core/error.hpp"
#include "interface_test_utils.hpp"

#include <gtest/gtest.h>

namespace bipot::contact {
namespace {

/// Appends `b` to `a` with its node and cell ids offset (no node is shared), renaming b's
/// regions and sets with `suffix`; returns the merged mesh.
Mesh merge(Mesh a, const Mesh& b, const std::string& suffix) {
  const Index node_offset = a.num_nodes(), cell_offset = a.num_cells();
  a.nodes.insert(a.nodes.end(), b.nodes.begin(), b.nodes.end());
  for (Index c = 0; c < b.num_cells(); ++c) {
    std::vector<Index> ids(b.cell(c), b.cell(c) + b.cell_num_nodes(c));
    for (Index& v : ids)
      v += node_offset;
    a.add_cell(b.cell_types[c], ids, a.region_id(b.region_name(b.cell_regions[c]) + suffix));
  }
  for (const auto& [name, facets] : b.facet_sets) {
    auto& out = a.facet_sets[name + suffix];
    for (Facet f : facets) {
      for (Index& v : f.nodes)
        v += node_offset;
      f.cell += cell_offset;
      out.push_back(f);
    }
  }
  for (const auto& [name, ids] : b.node_sets) {
    auto& out = a.node_sets[name + suffix];
    for (Index v : ids)
      out.push_back(v + node_offset);
  }
  return a;
}

/// Two 2 x ny rectangles [0, 1] x [0, 1] ("a") and [1, 2] x [0, 1] ("b"), not sharing nodes,
/// with facet sets "a_right" (x = 1, body a) and "b_left" (x = 1, body b).
Mesh two_bodies(int ny) {
  Mesh a = make_rectangle(0, 1, 2, 0, 1, ny, CellType::Quad4, "a");
  a.facet_sets["a_right"] = a.facet_sets.at("right");
  const Mesh b = make_rectangle(1, 2, 2, 0, 1, ny, CellType::Quad4, "b");
  return merge(a, b, "_b");
}

InterfaceDefinition facet_sets(const std::string& a, const std::string& b) {
  InterfaceDefinition d;
  d.name = "glue";
  d.facet_set_a = a;
  d.facet_set_b = b;
  d.initial_gap = 0.01;
  return d;
}

TEST(FacetSetPairing, CoincidentNodesArePaired) {
  Mesh mesh = two_bodies(3);
  const Mesh before = mesh;
  const auto ifaces =
      split_interfaces(mesh, Kinematics::PlaneStrain, {facet_sets("a_right", "left_b")}, false);
  EXPECT_EQ(mesh.num_nodes(), before.num_nodes()); // nothing split
  EXPECT_EQ(mesh.cell_nodes, before.cell_nodes);
  const Interface& iface = ifaces[0];
  EXPECT_EQ(iface.initial_gap, 0.01);
  ASSERT_EQ(iface.pairs.size(), 4u); // y = 0, 1/3, 2/3, 1
  const auto right_a = mesh.node_sets.at("right"), left_b = mesh.node_sets.at("left_b");
  for (const auto& p : iface.pairs) {
    EXPECT_TRUE(std::binary_search(right_a.begin(), right_a.end(), p.node_a));
    EXPECT_TRUE(std::binary_search(left_b.begin(), left_b.end(), p.node_b));
    EXPECT_EQ(mesh.nodes[p.node_a], mesh.nodes[p.node_b]);
    // Facets of "a_right" point out of body a: +x, exactly.
    EXPECT_EQ(p.normal, (std::array<double, 3>{1, 0, 0}));
  }
  // Length of the shared side, round-off only.
  EXPECT_NEAR(test::total_weight(iface), 1.0, 1e-14);
}

TEST(FacetSetPairing, FacetsWithoutCellAreOrientedOutOfBodyOne) {
  Mesh mesh = two_bodies(3);
  for (Facet& f : mesh.facet_sets["a_right"]) {
    f.cell = -1;
    std::swap(f.nodes[0], f.nodes[1]); // now pointing into body a
  }
  const auto ifaces =
      split_interfaces(mesh, Kinematics::PlaneStrain, {facet_sets("a_right", "left_b")}, false);
  for (const auto& p : ifaces[0].pairs)
    EXPECT_EQ(p.normal, (std::array<double, 3>{1, 0, 0}));
  for (const Facet& f : ifaces[0].facets_a)
    EXPECT_EQ(mesh.cell_regions[f.cell], mesh.regions.at("a"));
}

TEST(FacetSetPairing, MovedNodeIsReported) {
  Mesh mesh = two_bodies(3);
  // Node of a_right at (1, 1/3): moved 1e-3 m off its partner (tolerance 1e-9 x diagonal).
  const auto ids = test::nodes_where(mesh, [](const std::array<double, 3>& x) {
    return x[0] == 1.0 && std::abs(x[1] - 1.0 / 3) < 1e-12;
  });
  ASSERT_EQ(ids.size(), 2u);
  const Index moved = ids[0]; // body a's node comes first in the merged numbering
  mesh.nodes[moved][0] += 1e-3;
  const Mesh before = mesh;
  try {
    split_interfaces(mesh, Kinematics::PlaneStrain, {facet_sets("a_right", "left_b")}, false);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "interface 'glue': facet sets 'a_right' and 'left_b' do not match within 2.24e-09 "
              "m: 1 of 4 nodes of 'a_right' and 1 of 4 nodes of 'left_b' have no coincident "
              "partner; first of 'a_right': node " +
                  std::to_string(moved) + " at (1.001, 0.333333333)");
  }
  EXPECT_EQ(mesh.nodes, before.nodes);
}

TEST(FacetSetPairing, SharedNodesAreRejected) {
  Mesh mesh = test::pile_mesh(CellType::Quad4);
  // "top" and "right" share the corner (2, 0).
  const std::string msg = test::message_of([&] {
    split_interfaces(mesh, Kinematics::PlaneStrain, {facet_sets("top", "right")}, false);
  });
  EXPECT_NE(msg.find("facet sets 'top' and 'right' share 1 node(s), e.g. node "), std::string::npos)
      << msg;
  EXPECT_NE(msg.find(" at (2, 0); their nodes must be distinct"), std::string::npos) << msg;
}

TEST(CoincidentNodes, ManyNodesNearestWithinTolerance) {
  // 20001 nodes per side along a line, side b listed in reverse; one extra node of b slightly
  // off every 1000th node: the exact partner (distance 0) must win over it.
  Mesh mesh;
  std::vector<Index> a, b;
  const int n = 20001;
  for (int i = 0; i < n; ++i) {
    a.push_back(mesh.num_nodes());
    mesh.nodes.push_back({0.5, i * 1e-4, 0.25});
  }
  for (int i = n - 1; i >= 0; --i) {
    if (i % 1000 == 0) {
      b.push_back(mesh.num_nodes());
      mesh.nodes.push_back({0.5 + 5e-11, i * 1e-4, 0.25});
    }
    b.push_back(mesh.num_nodes());
    mesh.nodes.push_back({0.5, i * 1e-4, 0.25});
  }
  const auto partner = match_coincident_nodes(mesh, a, b, 1e-9);
  ASSERT_EQ(partner.size(), a.size());
  for (int i = 0; i < n; ++i) {
    ASSERT_GE(partner[i], 0);
    EXPECT_EQ(mesh.nodes[partner[i]], mesh.nodes[a[i]]) << i;
  }
  // Beyond the tolerance: no partner.
  mesh.nodes[a[7]][2] += 2e-9;
  EXPECT_EQ(match_coincident_nodes(mesh, a, b, 1e-9)[7], -1);
}

} // namespace
} // namespace bipot::contact
