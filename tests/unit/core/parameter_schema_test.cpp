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
  EXPECT_NE(s.markdown_table().find("\nRule: low <= high\n"), std::string::npos);
  EXPECT_EQ(s.find("extra")->summary(), "real, optional: absent means none");
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
