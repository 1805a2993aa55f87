#include "fem/core/error.hpp"
#include "fem/core/parameter_schema.hpp"
#include "fem/core/registry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

ParamSchema sample_schema() {
  ParamSchema s("sample", "a schema for tests");
  s.real("stiffness", "kN/m^3", "spring stiffness").positive();
  s.real("fraction", "", "a fraction").at_least(0).at_most(1).with_default(1.0);
  s.integer("count", "how many").at_least(1).with_default(3L);
  s.boolean("flag", "a switch").with_default(false);
  s.string("method", "how").one_of({"cg", "gmres"}).with_default(std::string("cg"));
  return s;
}

TEST(ParamSchema, RangeTextAndSummary) {
  const auto s = sample_schema();
  EXPECT_EQ(s.find("stiffness")->range_text(), "(0, inf)");
  EXPECT_EQ(s.find("fraction")->range_text(), "[0, 1]");
  EXPECT_EQ(s.find("flag")->range_text(), "");
  EXPECT_EQ(s.find("stiffness")->summary(), "real, required, (0, inf), kN/m^3: spring stiffness");
}

TEST(ParamSchema, ValidateFillsDefaultsAndConvertsIntegers) {
  ParameterSet p;
  p.set("stiffness", 5L); // an integer literal where a real is expected is fine
  const auto problems = validate(sample_schema(), p);
  EXPECT_TRUE(problems.empty());
  EXPECT_EQ(p.real("stiffness"), 5.0);
  EXPECT_EQ(p.real("fraction"), 1.0);
  EXPECT_EQ(p.integer("count"), 3);
  EXPECT_FALSE(p.boolean("flag"));
  EXPECT_EQ(p.string("method"), "cg");
}

TEST(ParamSchema, ValidateReportsEveryProblem) {
  ParameterSet p;
  p.set("fraction", 1.5);
  p.set("count", 2.5);
  p.set("method", std::string("gmress"));
  p.set("stifness", 1.0);
  const auto problems = validate(sample_schema(), p);
  ASSERT_EQ(problems.size(), 5u);
  std::map<std::string, std::string> by_key;
  for (const auto& pr : problems)
    by_key[pr.key] = pr.message;
  EXPECT_EQ(by_key["fraction"], "value 1.5 is out of range [0, 1]");
  EXPECT_EQ(by_key["count"], "expected an integer, got 2.5");
  EXPECT_EQ(by_key["method"],
            "value \"gmress\" is not one of: cg, gmres (did you mean \"gmres\"?)");
  EXPECT_EQ(by_key["stifness"],
            "unknown key for 'sample' (did you mean 'stiffness'?); allowed keys: "
            "stiffness, fraction, count, flag, method");
  EXPECT_EQ(by_key["stiffness"].substr(0, 22), "missing required key (");
}

// Cross-key rules run only once every key is valid on its own (so they may read any key),
// and report at their key; an optional key without default stays absent.
TEST(ParamSchema, RulesAndOptionalKeys) {
  ParamSchema s("pair", "two bounds");
  s.real("low", "", "lower bound");
  s.real("high", "", "upper bound");
  s.real("extra", "", "absent means none").optional();
  s.rule({"high", "low <= high", [](const ParameterSet& p) -> std::optional<std::string> {
            if (p.real("low") <= p.real("high")) return std::nullopt;
            return "value below low";
          }});
  ParameterSet p;
  p.set("low", 2.0);
  p.set("high", 1.0);
  auto problems = validate(s, p);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "high");
  EXPECT_EQ(problems[0].message, "value below low");
  EXPECT_FALSE(p.has("extra"));
  ParameterSet q;
  q.set("low", 2.0); // "high" missing: the rule must not run (it would throw)
  problems = validate(s, q);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "high");
  EXPECT_NE(s.markdown_table().find("\nRules between keys:\n- low <= high\n"), std::string::npos);
  EXPECT_EQ(s.find("extra")->summary(), "real, optional: absent means none");
}

// A rule between keys runs once every key is valid, with the defaults filled in; its problem
// names the key it concerns, validate_or_throw() prefixes the schema, describe() and the docs
// table state it.
TEST(ParamSchema, RulesBetweenKeys) {
  ParamSchema s = sample_schema();
  s.rule({"count", "count 1 needs method gmres",
          [](const ParameterSet& p) -> std::optional<std::string> {
            if (p.integer("count") != 1 || p.string("method") == "gmres") return std::nullopt;
            return "count 1 needs method 'gmres', got '" + p.string("method") + "'";
          }});
  ParameterSet p;
  p.set("stiffness", 1.0);
  p.set("count", 1L);
  auto problems = validate(s, p); // method defaults to cg
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "count");
  EXPECT_EQ(problems[0].message, "count 1 needs method 'gmres', got 'cg'");
  ParameterSet q;
  q.set("stiffness", 1.0);
  q.set("count", 1L);
  q.set("method", std::string("gmres"));
  EXPECT_TRUE(validate(s, q).empty());
  ParameterSet bad; // a missing key: the rule would read it, so it does not run
  bad.set("count", 1L);
  problems = validate(s, bad);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "stiffness");
  ParameterSet r;
  r.set("stiffness", 1.0);
  r.set("count", 1L);
  try {
    validate_or_throw(s, r);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0], "sample.count: count 1 needs method 'gmres', got 'cg'");
  }
  EXPECT_NE(s.describe().find("\n  rule: count 1 needs method gmres\n"), std::string::npos);
  EXPECT_NE(s.markdown_table().find("\nRules between keys:\n- count 1 needs method gmres\n"),
            std::string::npos);
}

TEST(ParamSchema, OpenAndClosedBounds) {
  ParamSpec spec;
  spec.greater_than(0).at_most(1);
  EXPECT_TRUE(spec.check(0.0).has_value());
  EXPECT_FALSE(spec.check(1e-300).has_value());
  EXPECT_FALSE(spec.check(1.0).has_value());
  EXPECT_TRUE(spec.check(1.0 + 1e-15).has_value());
  EXPECT_TRUE(spec.check(std::nan("")).has_value());
}

// A list of reals: the range applies to each entry, every bad entry is reported with its
// index, order is checked for a strictly increasing key, and the key's summary says both.
ParamSchema levels_schema() {
  ParamSchema s("levels", "a list key");
  s.real_list("at", "", "load factors")
      .greater_than(0)
      .at_most(1)
      .strictly_increasing()
      .because("fractions")
      .with_default(std::vector<double>{});
  s.real_list("free", "m", "any reals").optional();
  return s;
}

std::vector<ParamProblem> list_problems(const ParamValue& at) {
  ParameterSet p;
  p.set("at", at);
  return validate(levels_schema(), p);
}

TEST(ParamSchema, RealListChecksEachEntry) {
  ParameterSet p;
  p.set("at", std::vector<double>{0.25, 0.5, 1.0});
  ASSERT_TRUE(validate(levels_schema(), p).empty());
  EXPECT_EQ(p.real_list("at"), (std::vector<double>{0.25, 0.5, 1.0}));
  EXPECT_FALSE(p.has("free"));
  // An empty list: nothing to check, the same as the default.
  EXPECT_TRUE(list_problems(std::vector<double>{}).empty());

  // Out of range (both ends, open and closed) and out of order, each at its entry.
  auto problems = list_problems(std::vector<double>{0.5, 0.0, 0.75, 0.75, 1.25, 1.0});
  ASSERT_EQ(problems.size(), 4u);
  EXPECT_EQ(problems[0].key, "at");
  EXPECT_EQ(problems[0].entry, std::optional<std::size_t>(1));
  EXPECT_EQ(problems[0].message, "value 0 is out of range (0, 1]: fractions");
  EXPECT_EQ(problems[1].entry, std::optional<std::size_t>(3));
  EXPECT_EQ(problems[1].message,
            "value 0.75 does not exceed the entry before it (0.75): the entries must increase");
  EXPECT_EQ(problems[2].entry, std::optional<std::size_t>(4));
  EXPECT_EQ(problems[2].message, "value 1.25 is out of range (0, 1]: fractions");
  EXPECT_EQ(problems[3].entry, std::optional<std::size_t>(5)); // 1 after 1.25: in range, but
  EXPECT_EQ(problems[3].message,                               // not increasing
            "value 1 does not exceed the entry before it (1.25): the entries must increase");
  problems = list_problems(std::vector<double>{0.75, 0.5});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].entry, std::optional<std::size_t>(1));
  problems = list_problems(std::vector<double>{std::nan("")});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].entry, std::optional<std::size_t>(0));

  // A scalar where a list is expected, and a list where a real is.
  problems = list_problems(0.5);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].message, "expected a list of reals, got 0.5");
  EXPECT_FALSE(problems[0].entry.has_value());
  ParameterSet q;
  q.set("stiffness", std::vector<double>{1.0});
  problems = validate(sample_schema(), q);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].message, "expected a real, got [1]");

  // validate_or_throw names the entry.
  ParameterSet r;
  r.set("at", std::vector<double>{0.5, 2.0});
  try {
    validate_or_throw(levels_schema(), r);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0], "levels.at[1]: value 2 is out of range (0, 1]: fractions");
  }
}

TEST(ParamSchema, RealListSummaryAndTable) {
  const auto s = levels_schema();
  EXPECT_EQ(s.find("at")->interval_text(), "(0, 1]");
  EXPECT_EQ(s.find("at")->range_text(), "each in (0, 1], increasing");
  EXPECT_EQ(s.find("at")->summary(),
            "list of reals, default [], each in (0, 1], increasing: load factors");
  EXPECT_EQ(s.find("free")->range_text(), "");
  EXPECT_EQ(s.find("free")->summary(), "list of reals, optional, m: any reals");
  EXPECT_NE(s.markdown_table().find(
                "| `at` | list of reals | [] | each in (0, 1], increasing |  | load factors |"),
            std::string::npos)
      << s.markdown_table();
  EXPECT_EQ(format_value(std::vector<double>{0.1, 0.5, 1.0}), "[0.1, 0.5, 1]");
}

struct Thing {
  virtual ~Thing() = default;
  double value = 0;
};

TEST(Registry, CreateValidatesAndListsNames) {
  Registry<Thing> r("thing");
  r.add(sample_schema(), [](const ParameterSet& p) {
    auto t = std::make_unique<Thing>();
    t->value = p.real("stiffness") * p.real("fraction");
    return t;
  });
  ParameterSet p;
  p.set("stiffness", 2.0);
  p.set("fraction", 0.25);
  EXPECT_EQ(r.create("sample", p)->value, 0.5);
  EXPECT_EQ(r.names(), std::vector<std::string>{"sample"});
  try {
    r.create("sampel", p);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown thing 'sampel' (did you mean 'sample'?); registered: sample");
  }
}

} // namespace
} // namespace bipot
