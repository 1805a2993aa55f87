// Input errors of rigid bodies, each at its place, and the supports check with reference
// nodes.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "input_test_utils.hpp"

#include "apps/common/checked_model.hpp"

namespace bipot {
namespace {

// Line numbers of the text below are part of the expected messages.
const std::string base =
    "kinematics: plane_strain\n"                                                   // 1
    "mesh:\n  blocks:\n    cell: quad4\n"                                          // 2-4
    "    x: {breaks: [0, 1.0], cells: [2]}\n"                                      // 5
    "    y: {breaks: [0, 0.5, 0.6], cells: [1, 1]}\n"                              // 6
    "    regions: [soil, cap]\n"                                                   // 7
    "materials:\n"                                                                 // 8
    "  soil: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.3}\n" // 9
    "  cap: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.3}\n"  // 10
    "rigid_bodies:\n"                                                              // 11
    "  - {name: cap, region: cap}\n"                                               // 12
    "stages:\n"                                                                    // 13
    "  - name: press\n"                                                            // 14
    "    boundary_conditions:\n"                                                   // 15
    "      - {set: bottom, component: x, value: 0}\n"                              // 16
    "      - {set: bottom, component: y, value: 0}\n"                              // 17
    "    rigid_bodies:\n"                                                          // 18
    "      - {body: cap, component: y, value: -1.0e-3}\n";                         // 19

std::string check(const std::string& text) {
  try {
    app::checked_model(read_problem_text(text, "in.yaml", bipot::builtin_catalogue()),
                       bipot::builtin_catalogue());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RigidBodyInput, ValidInputHasNoProblem) {
  EXPECT_EQ(check(base), "");
}

TEST(RigidBodyInput, MissingRegionIsLocated) {
  const auto p = problems_of(replace(base, "region: cap}", "region: caps}"));
  EXPECT_TRUE(has(p, "in.yaml:12:5: rigid_bodies[0]: rigid body 'cap': no region named 'caps' in "
                     "the mesh (did you mean 'cap'?)"));
  EXPECT_TRUE(has(problems_of(replace(base, "region: cap}", "set: nowhere}")),
                  "rigid body 'cap': no node or facet set named 'nowhere'"));
  EXPECT_TRUE(has(problems_of(replace(base, "region: cap}", "region: cap, set: top}")),
                  "in.yaml:12:25: rigid_bodies[0].region: give exactly one of 'region'"));
}

// A boundary condition on a body's node would fight its reference node.
TEST(RigidBodyInput, ConditionOnABodysNodeIsAnError) {
  const auto p = problems_of(
      replace(base, "{set: bottom, component: x, value: 0}", "{set: top, component: x, value: 0}"));
  EXPECT_TRUE(has(p, "in.yaml:16:15: stages[0].boundary_conditions[0].set: node 6 at (0, 0.6) of "
                     "set 'top' belongs to rigid body 'cap'"));
}

TEST(RigidBodyInput, ConditionsOfTheReferenceNode) {
  auto p = problems_of(replace(base, "component: y, value: -1", "component: z, value: -1"));
  EXPECT_TRUE(has(p, "in.yaml:19:32: stages[0].rigid_bodies[0].component: unknown component 'z' "
                     "of a rigid body's reference node in plane_strain; allowed: x, y, rz"));
  p = problems_of(replace(base, "value: -1.0e-3}", "value: -1.0e-3, force: 2}"));
  EXPECT_TRUE(has(p, "stages[0].rigid_bodies[0].value: give exactly one of 'value'"));
  p = problems_of(base + "      - {body: cap, component: y, force: 3}\n");
  EXPECT_TRUE(has(p, "in.yaml:20:32: stages[0].rigid_bodies[1].component: component y of rigid "
                     "body 'cap' is already given by stages[0].rigid_bodies[0] (line 19)"));
  p = problems_of(replace(base, "body: cap,", "body: kap,"));
  EXPECT_TRUE(has(p, "in.yaml:19:16: stages[0].rigid_bodies[0].body: no rigid body named 'kap' "
                     "(did you mean 'cap'?); declared: cap"));
  p = problems_of(replace(replace(base, "kinematics: plane_strain", "kinematics: axisymmetric"),
                          "component: y, value: -1", "component: rz, value: -1"));
  EXPECT_TRUE(has(p, "allowed: z (a rigid body of revolution only moves axially)"));
}

// The supports check counts the reference node's prescribed components: a block held only
// by its rigid cap is held when the cap's three components are, free otherwise.
TEST(RigidBodyInput, ReferenceNodeHoldsItsBody) {
  const std::string held = replace(base,
                                   "    boundary_conditions:\n"
                                   "      - {set: bottom, component: x, value: 0}\n"
                                   "      - {set: bottom, component: y, value: 0}\n",
                                   "");
  const std::string message = check(held);
  EXPECT_NE(message.find("stage 'press': the body of regions 'soil' and 'cap' (cells 0-3): free "
                         "translation along x and rotation"),
            std::string::npos)
      << message;
  EXPECT_EQ(check(held + "      - {body: cap, component: x, value: 0}\n"
                         "      - {body: cap, component: rz, value: 0}\n"),
            "");
}

} // namespace
} // namespace bipot
