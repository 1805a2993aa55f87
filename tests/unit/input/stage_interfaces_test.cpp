// A stage's `interfaces:` (law or parameter changes): validated against the law's schema at
// the user's line, unknown interface names with the nearest one, and the resolved set (the
// parameters in force) carried from stage to stage.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "tests/unit/input/input_test_utils.hpp"

namespace bipot {
namespace {

// Two regions side by side with an interface, and two stages; `second` is inserted into the
// second stage (line 18 on).
std::string two_stages(const std::string& second) {
  return two_regions_text() +
         "interfaces:\n  - name: joint\n    between: [left, right]\n"                // 11-13
         "    law: coulomb_signorini\n    parameters: {friction_coefficient: 0.3}\n" // 14-15
         "stages:\n  - name: a\n"                                                    // 16-17
         "  - name: b\n" +                                                           // 18
         second;
}

TEST(StageInterfaces, ParametersMergeOverThoseInForceAndANewLawStartsFromItsDefaults) {
  const ProblemSpec spec = read_problem_text(
      two_stages("    interfaces: {joint: {law: rccm, parameters: {normal_stiffness: 1.0e6, "
                 "tangential_stiffness: 1.0e6, decohesion_energy: 0.01}}}\n"
                 "  - name: c\n    interfaces: {joint: {parameters: {friction_coefficient: "
                 "0.5}}}\n"),
      "in.yaml", bipot::builtin_catalogue());
  ASSERT_EQ(spec.stages.size(), 3u);
  EXPECT_TRUE(spec.stages[0].interface_laws.empty());
  ASSERT_EQ(spec.stages[1].interface_laws.size(), 1u);
  const auto& b = spec.stages[1].interface_laws[0];
  EXPECT_EQ(b.law, "rccm");
  EXPECT_EQ(b.parameters.real("friction_coefficient"), 0.0); // rccm's default, not 0.3
  EXPECT_EQ(b.parameters.real("initial_adhesion"), 1.0);
  ASSERT_EQ(spec.stages[2].interface_laws.size(), 1u);
  const auto& c = spec.stages[2].interface_laws[0];
  EXPECT_EQ(c.law, "rccm"); // unchanged, the parameters merged over stage b's
  EXPECT_EQ(c.parameters.real("friction_coefficient"), 0.5);
  EXPECT_EQ(c.parameters.real("normal_stiffness"), 1.0e6);
  EXPECT_EQ(c.parameters.real("decohesion_energy"), 0.01);
}

TEST(StageInterfaces, UnknownInterfaceNamesTheNearest) {
  const auto p = problems_of(
      two_stages("    interfaces: {jiont: {parameters: {friction_coefficient: 0.5}}}\n"));
  EXPECT_TRUE(has(p, "in.yaml:19:18: stages[1].interfaces.jiont: no interface named 'jiont' (did "
                     "you mean 'joint'?); interfaces: joint"));
}

TEST(StageInterfaces, BadParameterOfTheSecondStageIsLocated) {
  const auto p = problems_of(
      two_stages("    interfaces: {joint: {parameters: {friction_coefficient: -0.5}}}\n"));
  EXPECT_TRUE(has(p, "in.yaml:19:39: stages[1].interfaces.joint.parameters.friction_coefficient: "
                     "value -0.5 is out of range [0, inf)"));
  const auto q = problems_of(two_stages("    interfaces: {joint: {parameters: {frction: 0.5}}}\n"));
  EXPECT_TRUE(has(q, "stages[1].interfaces.joint.parameters.frction: unknown key"));
  EXPECT_TRUE(has(q, "friction_coefficient"));
}

TEST(StageInterfaces, NewLawIsValidatedAgainstItsOwnSchema) {
  const auto p = problems_of(two_stages("    interfaces: {joint: {law: rccm}}\n"));
  EXPECT_TRUE(has(p, "in.yaml:19:31: stages[1].interfaces.joint.law: parameters.normal_stiffness: "
                     "missing"));
  const auto q = problems_of(two_stages("    interfaces: {joint: {law: rcm}}\n"));
  EXPECT_TRUE(has(q, "stages[1].interfaces.joint.law: unknown interface law 'rcm' (did you mean "
                     "'rccm'?)"));
  const auto r = problems_of(two_stages("    interfaces: {joint: {}}\n"));
  EXPECT_TRUE(has(r, "stages[1].interfaces.joint: give a new law, new parameters, or both"));
  const auto s = problems_of(two_stages("    interfaces: {joint: {law: rccm, stiffness: 1}}\n"));
  EXPECT_TRUE(has(s, "stages[1].interfaces.joint.stiffness: unknown key"));
}

} // namespace
} // namespace bipot

namespace bipot {
namespace {

TEST(OutputCheckpoint, NamesStagesWithTheNearestOnATypo) {
  const std::string text = two_stages("output: {checkpoint: {after: [a, bb]}}\n");
  EXPECT_TRUE(has(problems_of(text), "in.yaml:19:30: output.checkpoint.after: no stage named "
                                     "'bb' (did you mean 'b'?); stages: a, b"));
  const ProblemSpec spec = read_problem_text(two_stages("output: {checkpoint: {after: [b]}}\n"),
                                             "in.yaml", bipot::builtin_catalogue());
  EXPECT_EQ(spec.output.checkpoint_after, std::vector<std::string>{"b"});
}

} // namespace
} // namespace bipot
