// No silent acceptance: what yaml-cpp or a narrowing conversion would let through unnoticed
// (a key given twice, an integer that wraps, a component the kinematics lacks, two values for
// one DOF, two outputs with one name, an endless input file) is an error at its line.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "tests/support/model_from_text.hpp"
#include "tests/unit/input/input_test_utils.hpp"

#include "fem/input/condition_checks.hpp"

#include <filesystem>
#include <fstream>

namespace bipot {
namespace {

// Plane strain, two regions side by side; line numbers on the right.
const std::string plane =
    "kinematics: plane_strain\n"                                                    // 1
    "mesh:\n"                                                                       // 2
    "  blocks:\n"                                                                   // 3
    "    cell: quad4\n"                                                             // 4
    "    x: {breaks: [0, 1, 2], cells: [2, 2]}\n"                                   // 5
    "    y: {breaks: [0, 1], cells: [2]}\n"                                         // 6
    "    regions: [left, right]\n"                                                  // 7
    "materials:\n"                                                                  // 8
    "  left: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}\n"  // 9
    "  right: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.3}\n" // 10
    "stages:\n"                                                                     // 11
    "  - name: load\n"                                                              // 12
    "    increments: 2\n"                                                           // 13
    "    boundary_conditions:\n"                                                    // 14
    "      - {set: bottom, component: y, value: 0}\n"                               // 15
    "      - {set: left, component: x, value: 0}\n"                                 // 16
    "    loads:\n"                                                                  // 17
    "      - {type: pressure, set: top, value: 10}\n";                              // 18

TEST(InputRobustness, ThePlaneStrainInputIsValid) {
  EXPECT_TRUE(problems_of(plane).empty());
}

TEST(InputRobustness, OnlyBoundedRegularFilesAreRead) {
  try {
    read_problem_file("/dev/zero", bipot::builtin_catalogue());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/zero: is a character device, not an input file (a "
                                     "regular YAML file is expected)");
  }
  const auto dir = std::filesystem::temp_directory_path();
  EXPECT_THROW(read_problem_file(dir.string(), bipot::builtin_catalogue()), InputError);
  // One byte over 64 MiB (sparse: nothing is written but the size).
  const auto big = dir / "bipot_input_too_large.yaml";
  std::ofstream(big).close();
  std::filesystem::resize_file(big, (std::size_t(64) << 20) + 1);
  try {
    read_problem_file(big.string(), bipot::builtin_catalogue());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              big.string() + ": the input file is larger than 64 MiB, the largest accepted");
  }
  std::filesystem::remove(big);
}

TEST(InputRobustness, KeyGivenTwice) {
  // At the top level, in a material's parameters, in materials, in a flow map of a list.
  EXPECT_TRUE(reports(plane, "stages:\n", "kinematics: three_d\nstages:\n",
                      "in.yaml:11:1: kinematics: key 'kinematics' given twice (first at line 1)"));
  EXPECT_TRUE(reports(plane, "0.3}\n  right", "0.3, youngs_modulus: 1}\n  right",
                      "in.yaml:9:76: materials.left.youngs_modulus: key 'youngs_modulus' given "
                      "twice (first at line 9)"));
  EXPECT_TRUE(reports(plane, "stages:\n", "  left: {type: linear_elastic}\nstages:\n",
                      "in.yaml:11:3: materials.left: key 'left' given twice (first at line 9)"));
  const std::string set_twice = replace(plane, "{set: left,", "{set: left, set: top,");
  EXPECT_TRUE(has(problems_of(set_twice),
                  "in.yaml:16:21: stages[0].boundary_conditions[1].set: key 'set' given "
                  "twice (first at line 16)"));
  // Each repetition is reported once, even where two readers walk the same map.
  EXPECT_EQ(problems_of(set_twice).size(), 1u);
}

TEST(InputRobustness, IntegersDoNotWrap) {
  // 2^32 + 1 would become 1 as an int.
  EXPECT_TRUE(reports(plane, "cells: [2]}", "cells: [4294967297]}",
                      "in.yaml:6:33: mesh.blocks.y.cells[0]: value 4294967297 is out of range "
                      "for an integer [-2147483648, 2147483647]"));
  EXPECT_TRUE(reports(plane, "increments: 2", "increments: 4294967297",
                      "in.yaml:13:5: stages[0].increments: value 4294967297 is out of range "
                      "for an integer [-2147483648, 2147483647]"));
  // Beyond a long too, and in a schema's parameters.
  EXPECT_TRUE(has(problems_of(plane + "linear_solver: {max_iterations: 99999999999999999999}\n"),
                  "in.yaml:19:17: linear_solver.max_iterations: value 99999999999999999999 "
                  "is out of range for an integer [-2147483648, 2147483647]"));
  EXPECT_TRUE(has(problems_of(plane + "linear_solver: {restart: 4294967297}\n"),
                  "linear_solver.restart: value 4294967297 is out of range for an integer"));
  // Not an integer at all, as before.
  EXPECT_TRUE(reports(plane, "increments: 2", "increments: 2.5",
                      "stages[0].increments: expected an integer, got '2.5'"));
}

TEST(InputRobustness, AbsurdSizesAreRefused) {
  EXPECT_TRUE(reports(plane, "increments: 2", "increments: 2000000000",
                      "in.yaml:13:5: stages[0].increments: value 2000000000 is out of range [1, "
                      "1000000]"));
  EXPECT_NO_THROW(read_problem_text(replace(plane, "increments: 2", "increments: 1000000"), "a",
                                    bipot::builtin_catalogue()));
  // 4e16 cells: refused while reading, before any memory is allocated for them.
  const std::string huge = replace(plane, "cells: [2, 2]}", "cells: [100000000, 100000000]}");
  EXPECT_TRUE(reports(huge, "cells: [2]}", "cells: [200000000]}",
                      "in.yaml:4:5: mesh.blocks: the mesh would have 40000000000000000 cells, "
                      "more than the 200000000 accepted"));
  // 1.0001e8 quads are accepted; as triangles they count twice, holes not at all.
  const std::string edge = replace(replace(plane, "cells: [2, 2]}", "cells: [5000, 5000]}"),
                                   "cells: [2]}", "cells: [10001]}");
  EXPECT_NO_THROW(read_problem_text(edge, "in.yaml", bipot::builtin_catalogue()));
  const std::string triangles = replace(edge, "cell: quad4", "cell: tri3");
  EXPECT_THROW(read_problem_text(triangles, "in.yaml", bipot::builtin_catalogue()), InputError);
  EXPECT_NO_THROW(read_problem_text(replace(triangles, "[left, right]", "[left, \"\"]"), "in.yaml",
                                    bipot::builtin_catalogue()));
}

TEST(InputRobustness, ComponentsOfTheKinematics) {
  EXPECT_TRUE(reports(plane, "component: x", "component: z",
                      "in.yaml:16:32: stages[0].boundary_conditions[1].component: unknown "
                      "component 'z' in plane_strain; allowed: x, y"));
  EXPECT_TRUE(reports(plane, "component: x", "component: r",
                      "unknown component 'r' in plane_strain; allowed: x, y"));
  // Axisymmetry names them r, z and accepts x, y.
  const std::string axi = replace(plane, "plane_strain", "axisymmetric");
  EXPECT_TRUE(problems_of(axi).empty());
  const std::string rz =
      replace(replace(axi, "component: x", "component: r"), "component: y", "component: z");
  const ProblemSpec spec = read_problem_text(rz, "in.yaml", bipot::builtin_catalogue());
  EXPECT_EQ(spec.stages[0].boundary_conditions[0].component, 1);
  EXPECT_EQ(spec.stages[0].boundary_conditions[1].component, 0);
  EXPECT_TRUE(reports(axi, "component: x", "component: w",
                      "unknown component 'w' in axisymmetric; allowed: r, z (or x, y)"));
}

TEST(InputRobustness, OneSetFixedTwiceInAStage) {
  const std::string twice = replace(plane, "      - {set: left, component: x, value: 0}\n",
                                    "      - {set: left, component: x, value: 0}\n"
                                    "      - {set: left, component: x, value: 1.0e-3}\n");
  EXPECT_TRUE(has(problems_of(twice),
                  "in.yaml:17:42: stages[0].boundary_conditions[2].value: component x of set "
                  "'left' is fixed to 1.0e-3 here and to 0 by "
                  "stages[0].boundary_conditions[1] (line 16) in the same stage"));
  // The same value twice is harmless, and each stage lists its own conditions.
  EXPECT_TRUE(problems_of(replace(twice, "value: 1.0e-3", "value: 0.0")).empty());
  EXPECT_TRUE(problems_of(plane + "  - name: move\n    boundary_conditions:\n"
                                  "      - {set: left, component: x, value: 1.0e-3}\n")
                  .empty());
}

TEST(InputRobustness, TwoSetsSharingANodeFixedDifferently) {
  // bottom and left share the corner node (0, 0): x = 1 mm there by one, 0 by the other.
  const std::string text = replace(plane, "      - {set: bottom, component: y, value: 0}\n",
                                   "      - {set: bottom, component: y, value: 0}\n"
                                   "      - {set: bottom, component: x, value: 1.0e-3}\n");
  const Model model = bipot::test::model_from_text(text, "in.yaml");
  const auto p = conflicting_conditions(model.spec, model.mesh);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(has(p, "in.yaml:17:15: stages[0].boundary_conditions[2].set: node 0 at (0, 0) of "
                     "set 'left' is also in set 'bottom', whose condition (in.yaml:16:15: "
                     "stages[0].boundary_conditions[1].set) fixes its component x to 0.001 in "
                     "the same stage, this one to 0"));
  // Equal values on the shared node are consistent.
  const Model same = bipot::test::model_from_text(replace(text, "1.0e-3", "0"), "in.yaml");
  EXPECT_TRUE(conflicting_conditions(same.spec, same.mesh).empty());
}

TEST(InputRobustness, NamesThatMustDiffer) {
  const std::string interfaces =
      "interfaces:\n"
      "  - {name: joint, between: [left, right], law: coulomb_signorini}\n"
      "  - {name: joint, between: [left, right], law: perfect_bonding}\n";
  EXPECT_TRUE(reports(plane, "stages:\n", interfaces + "stages:\n",
                      "in.yaml:13:12: interfaces[1].name: interface name 'joint' is already the "
                      "name of interfaces[0] (line 12); each interface needs its own, for its "
                      "output files interface_<name>.csv and interface_<name>.pvd"));
  EXPECT_TRUE(has(problems_of(plane + "  - name: load\n"),
                  "in.yaml:19:11: stages[1].name: stage name 'load' is already the name of "
                  "stages[0] (line 12)"));
  // A default name ("stage2") counts too.
  EXPECT_TRUE(reports(plane + "  - increments: 1\n", "name: load", "name: stage2",
                      "stages[1].name: stage name 'stage2' is already the name of stages[0]"));
}

} // namespace
} // namespace bipot
