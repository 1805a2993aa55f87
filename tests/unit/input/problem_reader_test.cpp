// Bad input is reported in one pass, each problem as file:line:col: key.path: message.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "tests/unit/input/input_test_utils.hpp"

namespace bipot {
namespace {

const std::string good =
    "kinematics: axisymmetric\n"                                                    // 1
    "mesh:\n"                                                                       // 2
    "  blocks:\n"                                                                   // 3
    "    cell: quad4\n"                                                             // 4
    "    x: {breaks: [0, 1], cells: [2]}\n"                                         // 5
    "    y: {breaks: [0, 1], cells: [2]}\n"                                         // 6
    "    regions: [soil]\n"                                                         // 7
    "materials:\n"                                                                  // 8
    "  soil: {type: linear_elastic, youngs_modulus: 3.0e4, poissons_ratio: 0.33}\n" // 9
    "stages:\n"                                                                     // 10
    "  - name: load\n"                                                              // 11
    "    boundary_conditions:\n"                                                    // 12
    "      - {set: bottom, component: z, value: 0}\n"                               // 13
    "    loads:\n"                                                                  // 14
    "      - {type: pressure, set: top, value: 10}\n";                              // 15

TEST(ProblemReader, GoodInputParses) {
  const ProblemSpec spec = read_problem_text(good, "in.yaml", bipot::builtin_catalogue());
  EXPECT_EQ(spec.kinematics, "axisymmetric");
  ASSERT_EQ(spec.stages.size(), 1u);
  EXPECT_EQ(spec.stages[0].boundary_conditions[0].component, 1);    // z is the axial component
  EXPECT_EQ(spec.materials[0].parameters.real("unit_weight"), 0.0); // default filled in
  EXPECT_TRUE(problems_of(good).empty());
}

TEST(ProblemReader, UnknownKeySuggestsNearest) {
  const auto p = problems_of(replace(good, "poissons_ratio", "poisson_ratio"));
  EXPECT_TRUE(has(p, "in.yaml:9:"));
  EXPECT_TRUE(has(p, "materials.soil.poisson_ratio: unknown key for 'linear_elastic' (did you "
                     "mean 'poissons_ratio'?)"));
  EXPECT_TRUE(has(p, "materials.soil.poissons_ratio: missing required key"));
  const auto q = problems_of(replace(good, "stages:", "stagse:"));
  EXPECT_TRUE(has(q, "in.yaml:10:1: stagse: unknown key (did you mean 'stages'?)"));
}

TEST(ProblemReader, UnknownMaterialListsRegistered) {
  const auto p = problems_of(replace(good, "type: linear_elastic", "type: cam_clay"));
  EXPECT_TRUE(has(p, "in.yaml:9:16: materials.soil.type: unknown material 'cam_clay'; "
                     "registered: drucker_prager, linear_elastic, mohr_coulomb, tresca, "
                     "von_mises"));
}

// A cross-key rule of a material's schema is reported at the key it concerns.
TEST(ProblemReader, MaterialRuleIsReportedAtItsKey) {
  const auto p = problems_of(replace(good, "type: linear_elastic",
                                     "type: mohr_coulomb, cohesion: 5, friction_angle: 30, "
                                     "dilatancy_angle: 35"));
  EXPECT_TRUE(has(p, "in.yaml:9:63: materials.soil.dilatancy_angle: value 35 deg exceeds "
                     "friction_angle 30 deg"));
}

TEST(ProblemReader, WrongTypeAndOutOfRange) {
  const auto p = problems_of(replace(good, "youngs_modulus: 3.0e4", "youngs_modulus: soft"));
  EXPECT_TRUE(has(p, "materials.soil.youngs_modulus: expected a real number, got 'soft'"));
  const auto q = problems_of(replace(good, "youngs_modulus: 3.0e4", "youngs_modulus: -3.0e4"));
  EXPECT_TRUE(has(q, "in.yaml:9:32: materials.soil.youngs_modulus: value -30000 is out of range "
                     "(0, inf) kPa"));
  const auto r = problems_of(replace(good, "cells: [2]}\n    y", "cells: [0]}\n    y"));
  EXPECT_TRUE(has(r, "mesh.blocks.x.cells: cell counts must be at least 1"));
}

TEST(ProblemReader, BlockDiagonalsAreValidated) {
  const std::string tri = replace(good, "cell: quad4", "cell: tri3");
  for (const char* d : {"right", "left", "alternating", "crossed"}) {
    const std::string text =
        replace(tri, "    x:", std::string("    diagonals: ") + d + "\n    x:");
    EXPECT_TRUE(problems_of(text).empty()) << d;
    EXPECT_EQ(read_problem_text(text, "in.yaml", bipot::builtin_catalogue()).mesh.diagonals, d);
  }
  EXPECT_EQ(read_problem_text(tri, "in.yaml", bipot::builtin_catalogue()).mesh.diagonals,
            "right"); // default
  // Crossed: 4 triangles per quad of the 2 x 2 grid.
  EXPECT_EQ(build_model(read_problem_text(replace(tri, "    x:", "    diagonals: crossed\n    x:"),
                                          "in.yaml", bipot::builtin_catalogue()),
                        bipot::builtin_catalogue())
                .mesh.num_cells(),
            16);
  EXPECT_TRUE(reports(tri, "    x:", "    diagonals: diagonal\n    x:",
                      "in.yaml:5:16: mesh.blocks.diagonals: unknown diagonal pattern 'diagonal'; "
                      "allowed: right, left, alternating, crossed"));
  EXPECT_TRUE(reports(good, "    x:", "    diagonals: left\n    x:",
                      "in.yaml:5:16: mesh.blocks.diagonals: diagonals applies to triangle cells "
                      "(tri3, tri6), not to quad4"));
  EXPECT_TRUE(reports(replace(good, "cell: quad4", "cell: tri6"),
                      "    x:", "    diagonals: crossed\n    x:",
                      "mesh.blocks.diagonals: diagonals 'crossed' (4 triangles around a centre "
                      "node) is available for tri3 cells only"));
}

TEST(ProblemReader, MissingRequiredKey) {
  const auto p =
      problems_of(replace(good, "    loads:\n      - {type: pressure, set: top, value: 10}\n",
                          "    loads:\n      - {type: pressure, set: top}\n"));
  EXPECT_TRUE(has(p, "stages[0].loads[0].value: missing required key"));
  const auto q = problems_of(
      replace(good, "kinematics: axisymmetric\n", "kinematics: axisymmetric\nmeshh: 1\n"));
  EXPECT_TRUE(has(q, "meshh: unknown key (did you mean 'mesh'?)"));
}

TEST(ProblemReader, EveryProblemIsReportedAtOnce) {
  std::string text = replace(good, "poissons_ratio: 0.33", "poissons_ratio: 0.7");
  text = replace(text, "component: z", "component: q");
  text = replace(text, "type: pressure", "type: pressur");
  const auto p = problems_of(text);
  EXPECT_EQ(p.size(), 3u);
  EXPECT_TRUE(has(p, "materials.soil.poissons_ratio: value 0.7 is out of range (-1, 0.5)"));
  EXPECT_TRUE(has(p, "stages[0].boundary_conditions[0].component: unknown component 'q'"));
  EXPECT_TRUE(has(p, "stages[0].loads[0].type: unknown load type 'pressur'"));
}

TEST(ProblemReader, MeshDependentChecksKeepTheUsersLine) {
  const auto p = problems_of(replace(good, "set: bottom", "set: botom"));
  EXPECT_TRUE(has(p, "in.yaml:13:15: stages[0].boundary_conditions[0].set: no node or facet set "
                     "named 'botom' in the mesh (did you mean 'bottom'?)"));
  const auto q = problems_of(replace(good, "  soil: {type", "  soils: {type"));
  EXPECT_TRUE(has(q, "in.yaml:9:3: materials.soils: no region named 'soils' in the mesh (did you "
                     "mean 'soil'?); available: soil"));
  EXPECT_TRUE(has(q, "region 'soil' of the mesh has no material"));
}

TEST(ProblemReader, SyntaxErrorHasLineAndColumn) {
  try {
    read_problem_text("mesh: {blocks: [1, 2\nstages: []\n", "bad.yaml", bipot::builtin_catalogue());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.yaml:"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("YAML syntax error"), std::string::npos) << e.what();
  }
}

TEST(ProblemReader, MissingFileIsNamed) {
  try {
    read_problem_file("/nonexistent/model.yaml", bipot::builtin_catalogue());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/model.yaml: cannot open the input file");
  }
}

TEST(ProblemReader, LinearSolverOptionsAreValidated) {
  const auto p = problems_of(good + "linear_solver: {method: bicgstab, tolerance: -1}\n");
  EXPECT_TRUE(has(p, "linear_solver.method: value \"bicgstab\" is not one of"));
  EXPECT_TRUE(has(p, "linear_solver.tolerance: value -1 is out of range"));
}

// A rule between keys of the linear solver's schema is found while reading (`bipot check`), at
// the key it concerns, not only when `run` constructs the solver; valid pairs pass.
TEST(ProblemReader, LinearSolverRulesAreFoundAtTheKey) {
  const auto p = problems_of(good + "linear_solver: {method: cg, preconditioner: lu}\n");
  EXPECT_TRUE(has(p, "in.yaml:16:29: linear_solver.preconditioner: preconditioner 'lu' needs "
                     "method 'gmres', got method 'cg'"));
  const auto q = problems_of(good + "linear_solver: {preconditioner: lu}\n"); // default cg
  EXPECT_TRUE(has(q, "in.yaml:16:17: linear_solver.preconditioner: preconditioner 'lu' needs "
                     "method 'gmres', got method 'cg'"));
  EXPECT_TRUE(problems_of(good + "linear_solver: {method: gmres, preconditioner: lu}\n").empty());
  // Only once every key is valid: a bad method is reported alone.
  const auto r = problems_of(good + "linear_solver: {method: bicg, preconditioner: lu}\n");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(has(r, "linear_solver.method: value \"bicg\" is not one of"));
}

} // namespace
} // namespace bipot

namespace bipot {
namespace {

// Two regions side by side (x fastest): base | block; an interface between them.
std::string with_interface(const std::string& interface_yaml, const std::string& extra = "") {
  return "kinematics: plane_strain\n"
         "mesh:\n  blocks:\n    cell: quad4\n"
         "    x: {breaks: [0, 1, 2, 3], cells: [1, 1, 1]}\n"
         "    y: {breaks: [0, 1], cells: [1]}\n"
         "    regions: [left, middle, right]\n"
         "materials:\n"
         "  left: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}\n"
         "  middle: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}\n"
         "  right: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}\n" +
         interface_yaml + extra +
         "stages:\n  - name: s\n    boundary_conditions:\n"
         "      - {set: bottom, component: y, value: 0}\n";
}

TEST(InterfaceInput, LawParametersOutOfRange) {
  const auto p = problems_of(
      with_interface("interfaces:\n  - name: joint\n    between: [left, middle]\n    law: rccm\n"
                     "    parameters: {normal_stiffness: -1.0, tangential_stiffness: 1.0e6, "
                     "decohesion_energy: 0.0, friction_coefficient: -0.1, initial_adhesion: 1.5, "
                     "adhesion_viscosity: -1}\n"));
  EXPECT_TRUE(has(p, "interfaces[0].parameters.normal_stiffness: value -1 is out of range (0, "
                     "inf) kN/m^3"));
  EXPECT_TRUE(has(p, "interfaces[0].parameters.decohesion_energy: value 0 is out of range"));
  EXPECT_TRUE(has(p, "interfaces[0].parameters.friction_coefficient: value -0.1 is out of "
                     "range [0, inf)"));
  EXPECT_TRUE(has(p, "interfaces[0].parameters.initial_adhesion: value 1.5 is out of range [0, "
                     "1]"));
  EXPECT_TRUE(has(p, "interfaces[0].parameters.adhesion_viscosity: value -1 is out of range"));
}

TEST(InterfaceInput, UnknownLawAndSolverListRegisteredNames) {
  const auto p = problems_of(
      with_interface("interfaces:\n  - name: joint\n    between: [left, middle]\n    law: rcm\n"));
  EXPECT_TRUE(has(p, "interfaces[0].law: unknown interface law 'rcm' (did you mean 'rccm'?); "
                     "registered: coulomb_signorini, perfect_bonding, rccm"));
  const auto q = problems_of(with_interface(
      "interfaces:\n  - name: joint\n    between: [left, middle]\n    law: perfect_bonding\n",
      "contact_solver: {type: uzawa}\n"));
  EXPECT_TRUE(has(q, "contact_solver.type: unknown contact solver 'uzawa'; registered: "
                     "bipotential_uzawa, generalized_newton, semismooth_newton"));
}

// A tolerance below what double precision can verify is refused with the reason, at check.
TEST(InterfaceInput, ToleranceBelowRoundOffIsRefused) {
  const auto p = problems_of(with_interface(
      "interfaces:\n  - name: joint\n    between: [left, middle]\n    law: coulomb_signorini\n",
      "contact_solver: {type: generalized_newton, tolerance: 1.0e-16}\n"));
  EXPECT_TRUE(has(p, "contact_solver.tolerance: value 1e-16 is out of range [1e-14, 1): below "
                     "1e-14 (about 50 machine epsilons) a relative residual is the round-off"));
}

TEST(InterfaceInput, RegionsThatDoNotTouch) {
  const auto p = problems_of(with_interface(
      "interfaces:\n  - name: joint\n    between: [left, right]\n    law: coulomb_signorini\n"));
  EXPECT_TRUE(has(p, "interface 'joint': regions 'left' and 'right' do not touch"));
  EXPECT_TRUE(has(p, "in.yaml:"));
}

} // namespace
} // namespace bipot

namespace bipot {
namespace {

TEST(BoxSets, SelectNodesInsideAndReportEmptyBoxes) {
  const std::string text = replace(good, "    regions: [soil]\n",
                                   "    regions: [soil]\n  sets:\n"
                                   "    axis_top: {min: [0, 1], max: [0, 1]}\n"
                                   "    mid_column: {min: [0.4, -1], max: [0.6, 2]}\n");
  const Model model = build_model(read_problem_text(text, "in.yaml", bipot::builtin_catalogue()),
                                  bipot::builtin_catalogue());
  // 2 x 2 cells on [0, 1]^2: one node at (0, 1), three on x = 0.5.
  ASSERT_EQ(model.mesh.node_sets.at("axis_top").size(), 1u);
  const auto& x = model.mesh.nodes[model.mesh.node_sets.at("axis_top")[0]];
  EXPECT_EQ(x[0], 0.0);
  EXPECT_EQ(x[1], 1.0);
  EXPECT_EQ(model.mesh.node_sets.at("mid_column").size(), 3u);
  // A box holding no node is found once the mesh exists; a malformed one while reading.
  const auto p = problems_of(replace(good, "    regions: [soil]\n",
                                     "    regions: [soil]\n  sets:\n"
                                     "    nowhere: {min: [5, 5], max: [6, 6]}\n"));
  EXPECT_TRUE(has(p, "in.yaml:9:5: mesh.sets.nowhere: no mesh node lies in this box"));
  const auto q = problems_of(replace(good, "    regions: [soil]\n",
                                     "    regions: [soil]\n  sets:\n"
                                     "    upside_down: {min: [1, 1], max: [0, 0]}\n"));
  ASSERT_EQ(q.size(), 1u);
  EXPECT_TRUE(has(q, "in.yaml:9:37: mesh.sets.upside_down.max: each max must be >= its min"));
}

} // namespace
} // namespace bipot

namespace bipot {
namespace {

// Region-restricted box sets keep one side's copies of split interface nodes; their errors
// and those of interface_gaps name the user's line.
TEST(BoxSets, RegionKeepsOneSideOfAnInterface) {
  const std::string iface =
      "interfaces:\n  - name: joint\n    between: [left, middle]\n    law: coulomb_signorini\n";
  const std::string sets = "  sets:\n"
                           "    seam_left: {min: [1, 0], max: [1, 1], region: left}\n"
                           "    seam_middle: {min: [1, 0], max: [1, 1], region: middle}\n"
                           "    seam: {min: [1, 0], max: [1, 1]}\n";
  const std::string text = replace(with_interface(iface), "    regions: [left, middle, right]\n",
                                   "    regions: [left, middle, right]\n" + sets);
  const Model model = build_model(read_problem_text(text, "in.yaml", bipot::builtin_catalogue()),
                                  bipot::builtin_catalogue());
  // Two nodes on x = 1; the split gives the middle region copies: 2 + 2 in the plain set.
  const auto& left = model.mesh.node_sets.at("seam_left");
  const auto& middle = model.mesh.node_sets.at("seam_middle");
  EXPECT_EQ(model.mesh.node_sets.at("seam").size(), 4u);
  ASSERT_EQ(left.size(), 2u);
  ASSERT_EQ(middle.size(), 2u);
  // Each pair joins a node of seam_left (body 1) to one of seam_middle (body 2).
  int paired = 0;
  for (const auto& p : model.interfaces[0].pairs) {
    const bool a_left = p.node_a == left[0] || p.node_a == left[1];
    const bool b_middle = p.node_b == middle[0] || p.node_b == middle[1];
    paired += a_left && b_middle;
  }
  EXPECT_EQ(paired, 2);

  const auto p = problems_of(replace(with_interface(iface), "    regions: [left, middle, right]\n",
                                     "    regions: [left, middle, right]\n  sets:\n"
                                     "    a: {min: [1, 0], max: [1, 1], region: midle}\n"));
  EXPECT_TRUE(has(p, "in.yaml:9:5: mesh.sets.a: no region named 'midle' in the mesh (did you "
                     "mean 'middle'?); available: left, middle, right"));
  // The box holds nodes, but none of the region's (checked after the split).
  const auto q = problems_of(replace(with_interface(iface), "    regions: [left, middle, right]\n",
                                     "    regions: [left, middle, right]\n  sets:\n"
                                     "    b: {min: [2.5, 0], max: [3, 1], region: left}\n"));
  EXPECT_TRUE(has(q, "in.yaml:9:5: mesh.sets.b: no node of region 'left' lies in this box"));
}

TEST(InterfaceInput, GapOfAnUnknownInterface) {
  const std::string text =
      with_interface("interfaces:\n  - name: joint\n    between: [left, middle]\n"
                     "    law: coulomb_signorini\n") +
      "    interface_gaps:\n      - {interface: jiont, value: -1.0e-4}\n";
  const auto p = problems_of(text);
  EXPECT_TRUE(has(p, "in.yaml:21:21: stages[0].interface_gaps[0].interface: no interface "
                     "named 'jiont' (did you mean 'joint'?); declared: joint"));
}

} // namespace
} // namespace bipot
