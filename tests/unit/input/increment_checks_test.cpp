// A prescribed displacement step larger than the model (small strain) is a warning naming the
// stage, the condition and both lengths; steps up to the model's size are not.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "tests/unit/input/input_test_utils.hpp"

#include "fem/input/increment_checks.hpp"

namespace bipot {
namespace {

// A 1 m x 1 m block: bounding-box diagonal sqrt(2) = 1.414213562 m. `stages` from line 9.
std::string block(const std::string& stages) {
  return "kinematics: plane_strain\n"                                                   // 1
         "mesh:\n"                                                                      // 2
         "  blocks:\n"                                                                  // 3
         "    x: {breaks: [0, 1], cells: [2]}\n"                                        // 4
         "    y: {breaks: [0, 1], cells: [2]}\n"                                        // 5
         "    regions: [body]\n"                                                        // 6
         "materials:\n"                                                                 // 7
         "  body: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}\n" // 8
         "stages:\n" +
         stages;
}

std::vector<std::string> warnings_of(const std::string& text) {
  const Model model = build_model(read_problem_text(text, "in.yaml", bipot::builtin_catalogue()),
                                  bipot::builtin_catalogue());
  return large_increment_warnings(model.spec, model.mesh);
}

std::string stage(const std::string& name, int increments, double top_y, bool reset = false) {
  return "  - name: " + name + "\n    increments: " + std::to_string(increments) +
         (reset ? "\n    reset_displacements: true" : "") +
         "\n    boundary_conditions:\n"
         "      - {set: bottom, component: y, value: 0}\n"
         "      - {set: bottom, component: x, value: 0}\n"
         "      - {set: top, component: y, value: " +
         std::to_string(top_y) + "}\n";
}

TEST(IncrementChecks, AStepLargerThanTheModelIsNamed) {
  const auto w = warnings_of(block(stage("pull", 1, 1000.0)));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0], "in.yaml:15:15: stages[0].boundary_conditions[2].set: stage 'pull': set 'top' "
                  "component y moves 1000 m per increment (from 0 to 1000 m in 1 increment), "
                  "more than the model's size, 1.414213562 m (its bounding-box diagonal): "
                  "small-strain kinematics cannot describe such a step; check the value's "
                  "units, or use more increments");
}

TEST(IncrementChecks, StepsUpToTheModelsSizeAreQuiet) {
  // 1000 m in 1000 increments: 1 m per increment < 1.414 m.
  EXPECT_TRUE(warnings_of(block(stage("pull", 1000, 1000.0))).empty());
  // 1.41 m in one increment, just below the diagonal; 1.42 m just above.
  EXPECT_TRUE(warnings_of(block(stage("pull", 1, 1.41))).empty());
  EXPECT_EQ(warnings_of(block(stage("pull", 1, 1.42))).size(), 1u);
}

TEST(IncrementChecks, AStepStartsFromThePreviousStagesValue) {
  // 1 m, then 1 m more: no step over 1.414 m; then 1 m to 3 m in one increment: 2 m.
  EXPECT_TRUE(warnings_of(block(stage("a", 1, 1.0) + stage("b", 1, 2.0))).empty());
  const auto w = warnings_of(block(stage("a", 1, 1.0) + stage("b", 1, 3.0)));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_TRUE(has(w, "stage 'b': set 'top' component y moves 2 m per increment (from 1 to 3 m"));
  // After reset_displacements the values start from 0 again: 0 to 1.42 m is over.
  const auto r = warnings_of(block(stage("a", 1, 1.0, true) + stage("b", 1, 1.42)));
  EXPECT_TRUE(has(r, "stage 'b': set 'top' component y moves 1.42 m per increment (from 0 to"));
}

} // namespace
} // namespace bipot
