// output.checkpoint within stages (`steps`, `every`): read as given, and refused at the user's
// line when a stage is unknown (with the nearest name), a step is outside the stage's planned
// increments, n < 1, or the stage is path-following.
#include "tests/unit/input/input_test_utils.hpp"

namespace bipot {
namespace {

// Two regions with an RCCM interface; stage `pull` (4 increments) and `trace` (3 increments,
// path-following); `output` is appended (line 24 on).
std::string with_output(const std::string& output) {
  return two_regions_text() +
         "interfaces:\n  - name: joint\n    between: [left, right]\n"                  // 11-13
         "    law: rccm\n    parameters: {normal_stiffness: 1.0e6, "                   // 14
         "tangential_stiffness: 1.0e6, decohesion_energy: 0.01}\n"                     // 15
         "stages:\n"                                                                   // 16
         "  - name: pull\n    increments: 4\n"                                         // 17-18
         "    boundary_conditions: [{set: left, component: x, value: 0}, "             // 19
         "{set: right, component: x, value: 1.0e-3}]\n"                                //
         "  - name: trace\n    increments: 3\n"                                        // 20-21
         "    control: {type: dissipation}\n" +                                        // 22
         std::string("    boundary_conditions: [{set: left, component: x, value: 0}, " // 23
                     "{set: right, component: x, value: 2.0e-3}]\n") +
         output;
}

TEST(OutputCheckpoint, StepsAndEveryAreReadAsGiven) {
  const ProblemSpec spec = read_problem_text(
      with_output("output: {checkpoint: {after: [pull], steps: [{stage: pull, step: 3}], "
                  "every: 2}}\n"),
      "in.yaml", builtin_catalogue());
  ASSERT_EQ(spec.output.checkpoint_steps.size(), 1u);
  EXPECT_EQ(spec.output.checkpoint_steps[0].stage, "pull");
  EXPECT_EQ(spec.output.checkpoint_steps[0].step, 3);
  EXPECT_EQ(spec.output.checkpoint_every, 2);
  // every 2: levels 2 and 4 of pull; step 3 asked for; never within the path-following stage.
  const StageSpec& pull = spec.stages[0];
  const StageSpec& trace = spec.stages[1];
  std::vector<int> at;
  for (int k = 1; k <= 4; ++k)
    if (spec.output.checkpoint_at(pull, k)) at.push_back(k);
  EXPECT_EQ(at, (std::vector<int>{2, 3, 4}));
  EXPECT_FALSE(spec.output.checkpoint_at(trace, 2));
  EXPECT_FALSE(spec.output.checkpoint_at(pull, 0)); // a sub-increment
}

TEST(OutputCheckpoint, UnknownStageStepOutOfRangeAndEveryBelowOneAreLocated) {
  const auto p = problems_of(with_output(
      "output:\n  checkpoint:\n    steps: [{stage: pul, step: 2}, {stage: pull, step: 5}, "
      "{stage: pull, step: 0}]\n    every: 0\n"));
  EXPECT_TRUE(has(p, "in.yaml:26:21: output.checkpoint.steps[0].stage: no stage named 'pul' "
                     "(did you mean 'pull'?); stages: pull, trace"));
  EXPECT_TRUE(has(p, "in.yaml:26:56: output.checkpoint.steps[1].step: step 5 is out of range "
                     "[1, 4]: stage 'pull' has 4 planned increments"));
  EXPECT_TRUE(has(p, "output.checkpoint.steps[2].step: step 0 is out of range [1, 4]"));
  EXPECT_TRUE(has(p, "in.yaml:27:12: output.checkpoint.every: value 0 is out of range [1, inf)"));
}

TEST(OutputCheckpoint, StepWithinAPathFollowingStageIsRefusedWithTheReason) {
  const auto p =
      problems_of(with_output("output: {checkpoint: {steps: [{stage: trace, step: 1}]}}\n"));
  EXPECT_TRUE(has(p, "output.checkpoint.steps[0].stage: stage 'trace' is path-following "
                     "(control: dissipation), whose path state a checkpoint does not hold"));
  EXPECT_TRUE(has(p, "use after: [trace] for its end"));
  const auto q = problems_of(with_output("output: {checkpoint: {}}\n"));
  EXPECT_TRUE(has(q, "output.checkpoint: expected at least one of after"));
}

} // namespace
} // namespace bipot
