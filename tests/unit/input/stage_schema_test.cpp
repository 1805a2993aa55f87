// A stage's own keys and its `control` mapping are read through their bound schemas
// (fem/input/stage_schema.hpp): every key reaches its member, each bad value and each broken
// rule between control keys is reported at its file:line:col, and the rules are listed by
// describe.
#include "fem/input/stage_schema.hpp"
#include "tests/unit/input/input_test_utils.hpp"

namespace bipot {
namespace {

// Two regions with an RCCM interface (path-following needs a contact law) and one stage
// `pull` whose own keys, from line 19 on, are `keys`.
std::string stage_with(const std::string& keys) {
  return two_regions_text() +
         "interfaces:\n  - name: joint\n    between: [left, right]\n"      // 11-13
         "    law: rccm\n    parameters: {normal_stiffness: 1.0e6, "       // 14
         "tangential_stiffness: 1.0e6, decohesion_energy: 0.01}\n"         // 15
         "stages:\n  - name: pull\n"                                       // 16-17
         "    boundary_conditions: [{set: left, component: x, value: 0}, " // 18
         "{set: right, component: x, value: 1.0e-3}]\n" +
         keys; // 19-
}

StageSpec read_stage(const std::string& keys) {
  const ProblemSpec spec = read_problem_text(stage_with(keys), "in.yaml", builtin_catalogue());
  EXPECT_EQ(spec.stages.size(), 1u);
  return spec.stages.empty() ? StageSpec{} : spec.stages[0];
}

std::vector<std::string> reading_problems(const std::string& keys) {
  try {
    read_problem_text(stage_with(keys), "in.yaml", builtin_catalogue());
  } catch (const InputError& e) {
    return e.problems();
  }
  return {};
}

// Every key given a value other than its default reaches its own member, exactly.
TEST(StageSchema, EveryKeyReachesItsMember) {
  const StageSpec defaults;
  const StageSpec a = read_stage("    increments: 7\n    duration: 2.5\n"
                                 "    reset_displacements: true\n    energy_tolerance: 0.25\n"
                                 "    control: {type: arc_length, arc_length: 0.003, "
                                 "max_increments: 44}\n    output_at: [0.125, 0.5, 1]\n");
  EXPECT_EQ(a.increments, 7);
  EXPECT_EQ(a.duration, 2.5);
  EXPECT_TRUE(a.reset_displacements);
  EXPECT_EQ(a.energy_tolerance, 0.25);
  EXPECT_EQ(a.output_at, (std::vector<double>{0.125, 0.5, 1.0}));
  EXPECT_EQ(a.control.type, "arc_length");
  EXPECT_EQ(a.control.arc_length, std::optional<double>(0.003));
  EXPECT_EQ(a.control.max_increments, std::optional<int>(44));
  EXPECT_FALSE(a.control.dissipation_step.has_value());
  EXPECT_EQ(a.control.where, "in.yaml:23:14: stages[0].control");
  // The list-valued keys keep their own readers.
  EXPECT_EQ(a.boundary_conditions.size(), 2u);
  EXPECT_EQ(a.name, "pull");

  const StageSpec d =
      read_stage("    control: {type: dissipation, dissipation_step: 0.02, max_increments: 9}\n");
  EXPECT_EQ(d.control.type, "dissipation");
  EXPECT_EQ(d.control.dissipation_step, std::optional<double>(0.02));
  EXPECT_EQ(d.control.max_increments, std::optional<int>(9));
  EXPECT_FALSE(d.control.arc_length.has_value());
  // Keys not given: the struct's own initial values (the schema's defaults).
  EXPECT_EQ(d.increments, defaults.increments);
  EXPECT_EQ(d.duration, defaults.duration);
  EXPECT_EQ(d.reset_displacements, defaults.reset_displacements);
  EXPECT_EQ(d.energy_tolerance, defaults.energy_tolerance);
  EXPECT_TRUE(d.output_at.empty());

  const StageSpec none = read_stage("");
  EXPECT_EQ(none.control.type, "ramp");
  EXPECT_FALSE(none.control.path_following());
}

// `control: dissipation`: the type alone, checked by the same schema and reported at `control`.
TEST(StageSchema, ControlShorthandIsTheType) {
  const StageSpec s = read_stage("    control: dissipation\n");
  EXPECT_EQ(s.control.type, "dissipation");
  EXPECT_FALSE(s.control.dissipation_step.has_value());
  EXPECT_FALSE(s.control.max_increments.has_value());
  EXPECT_EQ(s.control.where, "in.yaml:19:14: stages[0].control");
  EXPECT_TRUE(has(reading_problems("    control: arc_lenght\n"),
                  "in.yaml:19:14: stages[0].control: value \"arc_lenght\" is not one of: ramp, "
                  "arc_length, dissipation (did you mean \"arc_length\"?)"));
}

// Each rule between control keys fires at the key it names, with its line and column.
TEST(StageSchema, ControlRulesAreReportedAtTheirKey) {
  EXPECT_TRUE(has(reading_problems("    control: {type: ramp, arc_length: 1}\n"),
                  "in.yaml:19:27: stages[0].control.arc_length: only for type: arc_length "
                  "(this control is ramp)"));
  EXPECT_TRUE(has(reading_problems("    control: {type: arc_length, dissipation_step: 1}\n"),
                  "in.yaml:19:33: stages[0].control.dissipation_step: only for type: "
                  "dissipation (this control is arc_length)"));
  EXPECT_TRUE(has(reading_problems("    control: {type: ramp, max_increments: 5}\n"),
                  "in.yaml:19:27: stages[0].control.max_increments: only for path-following "
                  "controls (arc_length, dissipation)"));
  // A rule runs once the keys it reads are valid: with a type given wrongly, only the type.
  const auto p = reading_problems("    control: {type: rmap, arc_length: 1}\n");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(has(p, "in.yaml:19:15: stages[0].control.type: value \"rmap\" is not one of"));
}

// A bad value of each stage key is reported at its file:line:col, with the schema's range.
TEST(StageSchema, BadValuesAreLocated) {
  const auto p = reading_problems("    increments: 0\n    duration: -1\n"
                                  "    reset_displacements: maybe\n    energy_tolerance: 1.5\n"
                                  "    control: {type: arc_length, max_increments: 0, "
                                  "arc_lenght: 1}\n");
  EXPECT_TRUE(has(p, "in.yaml:19:5: stages[0].increments: value 0 is out of range [1, 1000000]"));
  EXPECT_TRUE(has(p, "in.yaml:20:5: stages[0].duration: value -1 is out of range (0, inf) s"));
  EXPECT_TRUE(has(p, "in.yaml:21:5: stages[0].reset_displacements: expected true or false, got "
                     "'maybe'"));
  EXPECT_TRUE(has(p, "in.yaml:22:5: stages[0].energy_tolerance: value 1.5 is out of range [0, 1): "
                     "a fraction of the work put in"));
  EXPECT_TRUE(has(p, "in.yaml:23:33: stages[0].control.max_increments: value 0 is out of range "
                     "[1, 1000000]"));
  EXPECT_TRUE(has(p, "in.yaml:23:52: stages[0].control.arc_lenght: unknown key for 'control' "
                     "(did you mean 'arc_length'?)"));
  EXPECT_EQ(p.size(), 6u);
  // An unknown stage key is still the stage map's (with the schema's keys among the allowed).
  EXPECT_TRUE(has(reading_problems("    increment: 2\n"),
                  "in.yaml:19:5: stages[0].increment: unknown key (did you mean 'increments'?)"));
}

// `output_at` (a list of reals): each bad entry is reported at its own file:line:col as
// output_at[i], with the range or the order it breaks; a list of the wrong kind at the key.
TEST(StageSchema, OutputAtIsCheckedEntryByEntry) {
  const std::string range = "is out of range (0, 1]: load factors are fractions of the stage";
  auto p = reading_problems("    output_at: [0.25, 1.5, 0]\n");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_TRUE(has(p, "in.yaml:19:23: stages[0].output_at[1]: value 1.5 " + range));
  EXPECT_TRUE(has(p, "in.yaml:19:28: stages[0].output_at[2]: value 0 " + range));
  // Block style: the entry's own line.
  p = reading_problems("    output_at:\n      - 0.5\n      - 0.75\n      - 0.75\n");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(has(p, "in.yaml:22:9: stages[0].output_at[2]: value 0.75 does not exceed the "
                     "entry before it (0.75): the entries must increase"));
  p = reading_problems("    output_at: [0.5, half, 1]\n");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(has(p, "in.yaml:19:22: stages[0].output_at[1]: expected a real number, got "
                     "'half'"));
  p = reading_problems("    output_at: 0.5\n");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(has(p, "in.yaml:19:5: stages[0].output_at: expected a list of real numbers, got "
                     "'0.5'"));
  // An empty list is the default: no stop of its own.
  EXPECT_TRUE(read_stage("    output_at: []\n").output_at.empty());
  EXPECT_TRUE(reading_problems("    output_at: []\n").empty());
}

// describe (and the docs' table) list the rules, so `bipot describe control` shows them.
TEST(StageSchema, DescribeListsTheRules) {
  const std::string text = control_schema().describe();
  for (const char* rule : {"rule: arc_length only with type: arc_length",
                           "rule: dissipation_step only with type: dissipation",
                           "rule: max_increments only with type: arc_length or dissipation"})
    EXPECT_NE(text.find(rule), std::string::npos) << text;
  EXPECT_EQ(control_schema().rules().size(), 3u);
}

} // namespace
} // namespace bipot
