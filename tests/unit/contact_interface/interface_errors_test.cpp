#include "contact/interface/interface_mesh.hpp"

#include "fem/core/error.hpp"
#include "interface_test_utils.hpp"

#include <gtest/gtest.h>

namespace bipot::contact {
namespace {

/// Three blocks along x: "a", "gap", "b"; a and b do not touch.
Mesh three_blocks() {
  BlockMeshSpec spec;
  spec.x = {{0, 1, 2, 3}, {1, 1, 1}, {}};
  spec.y = {{0, 1}, {1}, {}};
  spec.block_regions = {"a", "gap", "b"};
  return make_block_mesh(spec);
}

/// Calls split_interfaces on `mesh` expecting an InputError; returns its message and checks
/// that the mesh was left unchanged.
std::string input_error(Mesh& mesh, const std::vector<InterfaceDefinition>& defs) {
  const Mesh before = mesh;
  std::string msg;
  try {
    split_interfaces(mesh, Kinematics::PlaneStrain, defs, false);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    msg = e.what();
  }
  EXPECT_EQ(mesh.num_nodes(), before.num_nodes());
  EXPECT_EQ(mesh.cell_nodes, before.cell_nodes);
  return msg;
}

TEST(InterfaceErrors, RegionsThatDoNotTouch) {
  Mesh mesh = three_blocks();
  EXPECT_EQ(input_error(mesh, {test::between("i1", "a", "b", "pile.yaml:3:5: interfaces[0]")}),
            "pile.yaml:3:5: interfaces[0]: interface 'i1': regions 'a' and 'b' do not touch");
}

TEST(InterfaceErrors, UnknownRegionNamesTheNearest) {
  Mesh mesh = test::pile_mesh(CellType::Quad4);
  EXPECT_EQ(input_error(mesh, {test::between("shaft", "piel", "soil")}),
            "interface 'shaft': no region named 'piel' in the mesh (did you mean 'pile'?); "
            "regions: pile, soil");
  // Far from every name: no suggestion, still the list.
  EXPECT_EQ(input_error(mesh, {test::between("shaft", "pile", "concrete", "f.yaml:1:1: x")}),
            "f.yaml:1:1: x: interface 'shaft': no region named 'concrete' in the mesh; regions: "
            "pile, soil");
}

TEST(InterfaceErrors, EveryProblemIsReported) {
  Mesh mesh = test::pile_mesh(CellType::Quad4);
  InterfaceDefinition both = test::between("both", "pile", "soil");
  both.facet_set_a = "top";
  both.facet_set_b = "left";
  InterfaceDefinition neither;
  neither.name = "neither";
  InterfaceDefinition one = test::between("one", "pile", "");
  InterfaceDefinition sets;
  sets.name = "sets";
  sets.facet_set_a = "rigth";
  sets.facet_set_b = "right";
  try {
    split_interfaces(mesh, Kinematics::PlaneStrain,
                     {both, neither, one, test::between("self", "soil", "soil"), sets,
                      test::between("self", "pile", "soil")},
                     false);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    const std::vector<std::string> expected = {
        "interface 'both': give either two regions (between) or two facet sets, not both",
        "interface 'neither': give two regions (between: [a, b]) or two facet sets",
        "interface 'one': needs two regions, got only 'pile'",
        "interface 'self': the two regions are both 'soil'",
        "interface 'sets': no facet set named 'rigth' in the mesh (did you mean 'right'?); "
        "facet sets: bottom, left, right, top",
        "interface 'self': another interface has the same name",
    };
    EXPECT_EQ(e.problems(), expected);
  }
}

TEST(InterfaceErrors, KinematicsMustMatchTheMesh) {
  Mesh mesh = test::pile_mesh(CellType::Quad4);
  EXPECT_THROW(
      split_interfaces(mesh, Kinematics::ThreeD, {test::between("s", "pile", "soil")}, false),
      Error);
}

} // namespace
} // namespace bipot::contact
