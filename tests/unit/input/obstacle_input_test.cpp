// Input errors of rigid obstacles, each at its place (file:line:col: key.path: message).
#include "apps/catalogue/builtin_catalogue.hpp"
#include "input_test_utils.hpp"

#include "apps/common/checked_model.hpp"

namespace bipot {
namespace {

// Line numbers of the text below are part of the expected messages.
const std::string base = "kinematics: plane_strain\n"              // 1
                         "mesh:\n  blocks:\n    cell: quad4\n"     // 2-4
                         "    x: {breaks: [0, 1.0], cells: [2]}\n" // 5
                         "    y: {breaks: [0, 0.5], cells: [1]}\n" // 6
                         "    regions: [block]\n"                  // 7
                         "materials:\n"                            // 8
                         "  block: {type: linear_elastic, youngs_modulus: 1.0e5, "
                         "poissons_ratio: 0.3}\n"                                       // 9
                         "interfaces:\n"                                                // 10
                         "  - name: floor\n"                                            // 11
                         "    facet_sets: [bottom]\n"                                   // 12
                         "    obstacle: {type: plane, point: [0, 0], normal: [0, 1]}\n" // 13
                         "    law: coulomb_signorini\n"                                 // 14
                         "stages:\n"                                                    // 15
                         "  - name: press\n"                                            // 16
                         "    boundary_conditions:\n"                                   // 17
                         "      - {set: top, component: x, value: 0}\n"                 // 18
                         "      - {set: top, component: y, value: -1.0e-3}\n";          // 19

TEST(ObstacleInput, ValidInputHasNoProblem) {
  EXPECT_TRUE(problems_of(base).empty());
}

TEST(ObstacleInput, ZeroNormalIsLocated) {
  const auto p = problems_of(replace(base, "normal: [0, 1]", "normal: [0, 0]"));
  EXPECT_TRUE(has(p, "in.yaml:13:52: interfaces[0].obstacle.normal: the normal has zero length"));
}

TEST(ObstacleInput, UnknownTypeListsTheTypes) {
  const auto p = problems_of(replace(base, "type: plane", "type: wedge"));
  EXPECT_TRUE(has(p, "in.yaml:13:22: interfaces[0].obstacle.type: unknown obstacle type 'wedge'; "
                     "allowed: plane, line, circle, sphere, cylinder"));
}

TEST(ObstacleInput, TypeMustExistInTheKinematics) {
  const auto p = problems_of(
      replace(base, "type: plane, point: [0, 0], normal: [0, 1]", "type: sphere, radius: 1"));
  EXPECT_TRUE(has(p, "in.yaml:13:22: interfaces[0].obstacle.type: a sphere obstacle does not "
                     "exist in plane_strain; allowed: plane (or line), circle"));
}

TEST(ObstacleInput, KeysOfTheType) {
  auto p = problems_of(replace(base, "normal: [0, 1]", "normal: [0, 1], radius: 2"));
  EXPECT_TRUE(has(p, "interfaces[0].obstacle.radius: a plane obstacle takes point, normal, not "
                     "'radius'"));
  p = problems_of(replace(base, "type: plane, point: [0, 0], normal: [0, 1]",
                          "type: circle, point: [0, 2], radius: -1"));
  EXPECT_TRUE(has(p, "in.yaml:13:53: interfaces[0].obstacle.radius: value must be > 0 m"));
  p = problems_of(replace(base, "point: [0, 0]", "point: [0, 0, 0]"));
  EXPECT_TRUE(has(p, "in.yaml:13:36: interfaces[0].obstacle.point: expected 2 components, got 3"));
}

TEST(ObstacleInput, OneFacetSetOfTheBody) {
  auto p = problems_of(replace(base, "facet_sets: [bottom]", "facet_sets: [bottom, top]"));
  EXPECT_TRUE(has(p, "in.yaml:12:17: interfaces[0].facet_sets: an obstacle interface takes one "
                     "facet set (the body's side), got 2"));
  p = problems_of(replace(base, "facet_sets: [bottom]", "facet_sets: [botom]"));
  EXPECT_TRUE(has(p, "in.yaml:11:5: interfaces[0]: interface 'floor': no facet set named 'botom' "
                     "in the mesh (did you mean 'bottom'?)"));
}

TEST(ObstacleInput, DisplacementNamesAnObstacleInterface) {
  const std::string moved = base + "    obstacle_displacements:\n"
                                   "      - {interface: flor, value: [0, 1.0e-3]}\n"; // 21
  auto p = problems_of(moved);
  EXPECT_TRUE(has(p, "in.yaml:21:21: stages[0].obstacle_displacements[0].interface: no interface "
                     "named 'flor' (did you mean 'floor'?); interfaces with an obstacle: floor"));
  p = problems_of(replace(moved, "value: [0, 1.0e-3]", "value: [0, 1.0e-3, 0]"));
  EXPECT_TRUE(has(p, "in.yaml:21:34: stages[0].obstacle_displacements[0].value: expected 2 "
                     "displacement components (m)"));
}

// A node at the centre of a circle has no normal; perfect bonding needs the nodes on the
// surface.
TEST(ObstacleInput, NodesWhereThePairCannotBeBuilt) {
  auto p = problems_of(replace(base, "type: plane, point: [0, 0], normal: [0, 1]",
                               "type: circle, point: [0, 0], radius: 1"));
  EXPECT_TRUE(has(p, "in.yaml:11:5: interfaces[0]: interface 'floor': 1 of 3 nodes of 'bottom' "
                     "are on the circle's centre or axis"));
  p = problems_of(replace(replace(base, "point: [0, 0]", "point: [0, -0.1]"),
                          "law: coulomb_signorini", "law: perfect_bonding"));
  EXPECT_TRUE(has(p, "in.yaml:11:5: interfaces[0]: interface 'floor': perfect bonding holds the "
                     "nodes of 'bottom' where they are on the obstacle's surface; 3 of 3 nodes "
                     "are off it"));
}

// A block resting on a plane, with nothing pressing it and no support at all, is free;
// pressed by the obstacle's motion, or held by a bonded plane, it is not.
TEST(ObstacleInput, FreeBodiesBesideObstacles) {
  const std::string loose = replace(base,
                                    "    boundary_conditions:\n"
                                    "      - {set: top, component: x, value: 0}\n"
                                    "      - {set: top, component: y, value: -1.0e-3}\n",
                                    "");
  const auto check = [](const std::string& text) -> std::string {
    try {
      app::checked_model(read_problem_text(text, "in.yaml", bipot::builtin_catalogue()),
                         bipot::builtin_catalogue());
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(check(loose).find("hangs only on interface 'floor'"), std::string::npos)
      << check(loose);
  EXPECT_EQ(check(loose + "    obstacle_displacements:\n"
                          "      - {interface: floor, value: [0, 1.0e-3]}\n"),
            "");
  EXPECT_EQ(check(replace(loose, "law: coulomb_signorini", "law: perfect_bonding")), "");
}

// A condition on a node that a bonded obstacle holds is an error at the condition.
TEST(ObstacleInput, ConditionOnANodeHeldByABondedObstacle) {
  const std::string text = replace(replace(base, "law: coulomb_signorini", "law: perfect_bonding"),
                                   "      - {set: top, component: x, value: 0}\n",
                                   "      - {set: left, component: x, value: 0}\n");
  std::string message;
  try {
    app::checked_model(read_problem_text(text, "in.yaml", bipot::builtin_catalogue()),
                       bipot::builtin_catalogue());
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("in.yaml:18:15: stages[0].boundary_conditions[0].set: node 0 at (0, 0) "
                         "of set 'left' is held by a perfectly bonded obstacle"),
            std::string::npos)
      << message;
}

// A path-following stage does not scale the obstacle's motion by its load factor.
TEST(ObstacleInput, PathFollowingStageCannotMoveTheObstacle) {
  const auto p = problems_of(base + "    control: arc_length\n"
                                    "    obstacle_displacements:\n"
                                    "      - {interface: floor, value: [0, 1.0e-3]}\n");
  EXPECT_TRUE(has(p, "control arc_length: a path-following stage cannot also move obstacles or "
                     "rigid bodies"));
}

} // namespace
} // namespace bipot
