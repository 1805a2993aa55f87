// ParamSchemaOf: keys bound to struct members fill the struct from validated input, write it
// back, validate a struct built in code with the input's messages, and run typed rules.
#include "fem/core/error.hpp"
#include "fem/core/parameter_binding.hpp"
#include "fem/core/registry.hpp"

#include <gtest/gtest.h>

namespace bipot {
namespace {

enum class Shape { Round, Square };

struct Sample {
  double stiffness = 0;
  double ratio = 0.25;
  std::optional<double> cutoff = std::nullopt;
  int count = 3;
  long big = 0;
  std::optional<int> limit = std::nullopt;
  bool verbose = false;
  std::string label = "a";
  Shape shape = Shape::Round;
  std::vector<double> levels = {0.5, 1.0};
};

ParamSchemaOf<Sample> sample_schema() {
  ParamSchemaOf<Sample> s("sample", "a struct with one member of every kind");
  s.real("stiffness", &Sample::stiffness, "kPa", "required, > 0").positive();
  s.real("ratio", &Sample::ratio, "", "[0, 1]").at_least(0.0).at_most(1.0).defaulted();
  s.real("cutoff", &Sample::cutoff, "kPa", "optional").non_negative();
  s.integer("count", &Sample::count, "at least 1").at_least(1).defaulted();
  s.integer("big", &Sample::big, "any").with_default(0L);
  s.integer("limit", &Sample::limit, "optional").at_least(0);
  s.boolean("verbose", &Sample::verbose, "flag").defaulted();
  s.string("label", &Sample::label, "free text").defaulted();
  s.choice("shape", &Sample::shape, {{"round", Shape::Round}, {"square", Shape::Square}}, "enum")
      .defaulted();
  s.real_list("levels", &Sample::levels, "m", "increasing, >= 0")
      .non_negative()
      .strictly_increasing()
      .defaulted();
  s.rule("ratio", "ratio <= 0.5 when shape is square", [](const Sample& p) {
    return p.shape == Shape::Square && p.ratio > 0.5
               ? std::optional<std::string>("value " + format_value(p.ratio) +
                                            " exceeds 0.5 for a square")
               : std::nullopt;
  });
  return s;
}

// What validate_or_throw reports for `given`, "" if nothing.
std::string input_error(ParameterSet given) {
  try {
    validate_or_throw(sample_schema(), given);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// What checked() reports for `p`, "" if nothing.
std::string code_error(const Sample& p) {
  try {
    sample_schema().checked(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ParamBinding, FillsEveryMemberFromValidatedInput) {
  const auto schema = sample_schema();
  ParameterSet given;
  given.set("stiffness", 2L); // an integer for a real key is converted by validate()
  given.set("ratio", 0.375);
  given.set("cutoff", 4.5);
  given.set("count", 7L);
  given.set("big", 1L << 40);
  given.set("limit", 11L);
  given.set("verbose", true);
  given.set("label", std::string("xyz"));
  given.set("shape", std::string("square"));
  given.set("levels", std::vector<double>{0.0, 0.125, 3.5});
  ASSERT_TRUE(validate(schema, given).empty());
  const Sample p = *schema.fill(given);
  EXPECT_EQ(p.stiffness, 2.0);
  EXPECT_EQ(p.ratio, 0.375);
  ASSERT_TRUE(p.cutoff.has_value());
  EXPECT_EQ(*p.cutoff, 4.5);
  EXPECT_EQ(p.count, 7);
  EXPECT_EQ(p.big, 1L << 40);
  ASSERT_TRUE(p.limit.has_value());
  EXPECT_EQ(*p.limit, 11);
  EXPECT_TRUE(p.verbose);
  EXPECT_EQ(p.label, "xyz");
  EXPECT_EQ(p.shape, Shape::Square);
  EXPECT_EQ(p.levels, (std::vector<double>{0.0, 0.125, 3.5}));
  // Written back, the struct gives the same values by key.
  EXPECT_EQ(schema.to_parameters(p).values(), given.values());
}

TEST(ParamBinding, AbsentKeysTakeTheirDefaultsOrStayEmpty) {
  const auto schema = sample_schema();
  ParameterSet given;
  given.set("stiffness", 1.0);
  ASSERT_TRUE(validate(schema, given).empty());
  const Sample p = *schema.fill(given);
  EXPECT_FALSE(p.cutoff.has_value());
  EXPECT_FALSE(p.limit.has_value());
  EXPECT_EQ(p.ratio, 0.25);
  EXPECT_EQ(p.count, 3);
  EXPECT_EQ(p.shape, Shape::Round);
  EXPECT_EQ(p.levels, (std::vector<double>{0.5, 1.0}));
  EXPECT_FALSE(schema.to_parameters(p).has("cutoff"));
  // fill() also takes defaults a caller's set lacks (it does not validate again).
  ParameterSet bare;
  bare.set("stiffness", 1.0);
  EXPECT_EQ(schema.fill(bare)->count, 3);
  EXPECT_EQ(schema.fill(bare)->label, "a");
}

TEST(ParamBinding, EveryKeyIsBoundAndTheSchemaStaysUntypedForTheChecker) {
  const auto schema = sample_schema();
  for (const auto& key : schema.keys())
    EXPECT_TRUE(schema.is_bound(key)) << key;
  EXPECT_FALSE(schema.is_bound("nothing"));
  const ParamSchema& untyped = schema;
  EXPECT_EQ(untyped.find("shape")->choices, (std::vector<std::string>{"round", "square"}));
  EXPECT_FALSE(untyped.find("cutoff")->required); // a std::optional member makes the key optional
  EXPECT_FALSE(untyped.find("cutoff")->default_value.has_value());
  EXPECT_TRUE(untyped.find("stiffness")->required);
}

TEST(ParamBinding, CodeLevelStructReportsWhatTheInputWould) {
  Sample good;
  good.stiffness = 1.0;
  EXPECT_EQ(code_error(good), "");
  EXPECT_EQ(sample_schema().checked(good)->stiffness, 1.0);

  Sample bad = good;
  bad.stiffness = -3.0;
  bad.cutoff = -1.0;
  ParameterSet given;
  given.set("stiffness", -3.0);
  given.set("cutoff", -1.0);
  const std::string expected = input_error(given);
  EXPECT_EQ(expected, "sample.cutoff: value -1 is out of range [0, inf) kPa\n"
                      "sample.stiffness: value -3 is out of range (0, inf) kPa");
  EXPECT_EQ(code_error(bad), expected);

  // A cross-key rule written on the struct, the same from input and from code.
  Sample square = good;
  square.shape = Shape::Square;
  square.ratio = 0.75;
  EXPECT_EQ(code_error(square), "sample.ratio: value 0.75 exceeds 0.5 for a square");
  given = ParameterSet{};
  given.set("stiffness", 1.0);
  given.set("shape", std::string("square"));
  given.set("ratio", 0.75);
  EXPECT_EQ(input_error(given), code_error(square));

  // A list member: each bad entry named by its index, the same from input and from code.
  Sample unordered = good;
  unordered.levels = {-1.0, 2.0, 2.0};
  given = ParameterSet{};
  given.set("stiffness", 1.0);
  given.set("levels", unordered.levels);
  EXPECT_EQ(input_error(given),
            "sample.levels[0]: value -1 is out of range [0, inf) m\n"
            "sample.levels[2]: value 2 does not exceed the entry before it (2): the entries "
            "must increase");
  EXPECT_EQ(code_error(unordered), input_error(given));
}

TEST(ParamBinding, MissingRequiredKeyMessage) {
  EXPECT_EQ(
      input_error(ParameterSet{}),
      "sample.stiffness: missing required key (real, required, (0, inf), kPa: required, > 0)");
}

// A type built by the registry from the filled struct, as a law or material is.
struct Spring {
  struct Parameters {
    double stiffness = 0;
  };
  static ParamSchemaOf<Parameters> schema() {
    ParamSchemaOf<Parameters> s("spring", "a spring");
    s.real("stiffness", &Parameters::stiffness, "kN/m", "k").positive();
    return s;
  }
  explicit Spring(Checked<Parameters> p) : k(p->stiffness) {}
  virtual ~Spring() = default;
  double k;
};

TEST(ParamBinding, RegistryBuildsFromTheFilledStruct) {
  Registry<Spring> r("spring");
  r.add<Spring>();
  ParameterSet p;
  p.set("stiffness", 4.0);
  EXPECT_EQ(r.create("spring", p)->k, 4.0);
  EXPECT_EQ(r.create_validated("spring", p)->k, 4.0);
  p.set("stiffness", 0.0);
  try {
    r.create("spring", p);
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "spring.stiffness: value 0 is out of range (0, inf) kN/m");
  }
  // The reader has validated already: create_validated() does not check a second time.
  EXPECT_EQ(r.create_validated("spring", p)->k, 0.0);
}

// defaulted() takes the default from the member's initializer (the value is written once, in
// the struct), for every kind of key; a key with no member value to take refuses it.
TEST(ParamSchemaOf, DefaultedTakesTheMembersInitialValue) {
  const ParamSchemaOf<Sample> s = sample_schema();
  auto default_of = [&](const std::string& key) { return *s.find(key)->default_value; };
  EXPECT_EQ(std::get<double>(default_of("ratio")), 0.25);
  EXPECT_EQ(std::get<long>(default_of("count")), 3L);
  EXPECT_EQ(std::get<bool>(default_of("verbose")), false);
  EXPECT_EQ(std::get<std::string>(default_of("label")), "a");
  EXPECT_EQ(std::get<std::string>(default_of("shape")), "round");
  EXPECT_EQ(std::get<std::vector<double>>(default_of("levels")), (std::vector<double>{0.5, 1.0}));
  EXPECT_TRUE(s.find("stiffness")->required);
  ParamSchemaOf<Sample> other("other", "");
  EXPECT_THROW(other.real("cutoff", &Sample::cutoff, "kPa", "optional").defaulted(),
               std::logic_error);
  ParamSchema untyped("untyped", "");
  EXPECT_THROW(untyped.real("x", "", "unbound").defaulted(), std::logic_error);
}

// A rule that names the keys it reads runs once those are valid, though another key has a
// problem (both are reported); a rule without `reads` waits until every key is valid.
TEST(ParamSchemaOf, RuleWithItsKeysRunsDespiteProblemsElsewhere) {
  struct Box {
    double low = 0, high = 0, other = 0;
  };
  for (const bool named : {true, false}) {
    ParamSchemaOf<Box> s("box", "");
    s.real("low", &Box::low, "", "").defaulted();
    s.real("high", &Box::high, "", "").defaulted();
    s.real("other", &Box::other, "", "positive").positive();
    auto check = [](const Box& b) -> std::optional<std::string> {
      return b.low < b.high ? std::nullopt : std::optional<std::string>("low >= high");
    };
    if (named)
      s.rule("high", "low < high", check, {"low", "high"});
    else
      s.rule("high", "low < high", check);
    ParameterSet given;
    given.set("low", 2.0);
    given.set("high", 1.0);
    given.set("other", -1.0);
    const auto problems = validate(s, given);
    ASSERT_EQ(problems.size(), named ? 2u : 1u);
    EXPECT_EQ(problems[0].key, "other");
    if (named) {
      EXPECT_EQ(problems[1].key, "high");
      EXPECT_EQ(problems[1].message, "low >= high");
    }
  }
}

} // namespace
} // namespace bipot
