// Every schema bipot ships binds every key to its own member, generically: values are made up
// from each key's type and range, never by naming keys, so a new key or schema is covered
// without editing this file (a new material or law must only be added to the lists below,
// which are compared with the registries).
#include "apps/pile_pullout/pile_input.hpp"
#include "contact/laws/coulomb_signorini.hpp"
#include "contact/laws/interface_law_registry.hpp"
#include "contact/laws/perfect_bonding.hpp"
#include "contact/laws/rccm.hpp"
#include "contact/solver/contact_solver_options.hpp"
#include "fem/core/error.hpp"
#include "fem/input/stage_schema.hpp"
#include "fem/linalg/linear_solver.hpp"
#include "materials/drucker_prager.hpp"
#include "materials/linear_elastic.hpp"
#include "materials/material_registry.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/tresca.hpp"
#include "materials/von_mises.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace bipot {
namespace {

// A value for every key, distinct across keys of one type and from each key's default.
ParameterSet distinct_values(const ParamSchema& schema) {
  ParameterSet s;
  long i = 0;
  for (const auto& spec : schema.specs()) {
    ++i;
    switch (spec.type) {
    case ParamType::Real:
      s.set(spec.name, 1.5 + 0.125 * static_cast<double>(i));
      break;
    case ParamType::Integer:
      s.set(spec.name, 1000L + i);
      break;
    case ParamType::Boolean:
      s.set(spec.name, !(spec.default_value && std::get<bool>(*spec.default_value)));
      break;
    case ParamType::String: {
      const std::string fallback = "text" + std::to_string(i);
      if (spec.choices.empty()) {
        s.set(spec.name, fallback);
        break;
      }
      const bool back_is_default =
          spec.default_value && std::get<std::string>(*spec.default_value) == spec.choices.back();
      s.set(spec.name, back_is_default ? spec.choices.front() : spec.choices.back());
      break;
    }
    case ParamType::RealList:
      s.set(spec.name, std::vector<double>{0.125 * static_cast<double>(i),
                                           0.5 + 0.25 * static_cast<double>(i)});
      break;
    }
  }
  return s;
}

// A valid value for every key: its default, else the middle of its range, else 1 inside an
// open-ended one. (The test asserts that validate() accepts the result.)
ParameterSet valid_values(const ParamSchema& schema) {
  ParameterSet s;
  for (const auto& spec : schema.specs()) {
    if (spec.default_value) {
      s.set(spec.name, *spec.default_value);
      continue;
    }
    double x = 1.0;
    if (std::isfinite(spec.lower) && std::isfinite(spec.upper))
      x = 0.5 * (spec.lower + spec.upper);
    else if (std::isfinite(spec.lower))
      x = spec.lower + 1.0;
    else if (std::isfinite(spec.upper))
      x = spec.upper - 1.0;
    if (spec.type == ParamType::Integer)
      s.set(spec.name, static_cast<long>(std::ceil(x)));
    else
      s.set(spec.name, x);
  }
  return s;
}

std::string input_error(const ParamSchema& schema, ParameterSet given) {
  try {
    validate_or_throw(schema, given);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Fill from distinct values, write back: every key must come back with its own value (a key
// bound to no member, or two keys to one member, loses one). An optional key left out stays
// empty.
template <class P> void expect_every_key_bound(const ParamSchemaOf<P>& schema) {
  SCOPED_TRACE(schema.name());
  for (const auto& key : schema.keys())
    EXPECT_TRUE(schema.is_bound(key)) << key;
  const ParameterSet given = distinct_values(schema);
  const ParameterSet back = schema.to_parameters(*schema.fill(given));
  for (const auto& [key, value] : given.values()) {
    ASSERT_TRUE(back.has(key)) << key << " is not written back";
    EXPECT_EQ(format_value(back.values().at(key)), format_value(value)) << key;
  }
  EXPECT_EQ(back.values().size(), given.values().size());
  for (const auto& spec : schema.specs()) {
    if (spec.required || spec.default_value) continue;
    ParameterSet copy;
    for (const auto& [key, value] : given.values())
      if (key != spec.name) copy.set(key, value);
    EXPECT_FALSE(schema.to_parameters(*schema.fill(copy)).has(spec.name)) << spec.name;
  }
}

// For objects built from code: the struct's own defaults are the schema's.
template <class P> void expect_struct_defaults_match(const ParamSchemaOf<P>& schema) {
  SCOPED_TRACE(schema.name());
  const ParameterSet d = schema.to_parameters(P{});
  for (const auto& spec : schema.specs())
    if (spec.default_value) {
      ASSERT_TRUE(d.has(spec.name)) << spec.name;
      EXPECT_EQ(format_value(d.values().at(spec.name)), format_value(*spec.default_value))
          << spec.name;
    }
}

// T(Parameters) with a value below a key's lower bound throws what the input file would get.
template <class T> void expect_code_construction_checked() {
  const auto schema = T::schema();
  SCOPED_TRACE(schema.name());
  ParameterSet valid = valid_values(schema);
  ASSERT_EQ(input_error(schema, valid), "");
  EXPECT_NO_THROW({ T object(*schema.fill(valid)); });
  int bad_keys = 0;
  for (const auto& spec : schema.specs()) {
    if (spec.type != ParamType::Real || !std::isfinite(spec.lower)) continue;
    ++bad_keys;
    ParameterSet bad = valid;
    bad.set(spec.name, spec.lower - 1.0);
    const std::string expected = input_error(schema, bad);
    EXPECT_NE(expected.find(schema.name() + "." + spec.name + ": value"), std::string::npos)
        << expected;
    try {
      T object(*schema.fill(bad)); // the plain struct: the constructor validates it
      ADD_FAILURE() << spec.name << ": no exception";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), expected);
    }
  }
  if (!schema.specs().empty()) {
    EXPECT_GT(bad_keys, 0);
  }
}

template <class... T> std::set<std::string> check_types() {
  std::set<std::string> names;
  (
      [&] {
        expect_every_key_bound(T::schema());
        expect_struct_defaults_match(T::schema());
        expect_code_construction_checked<T>();
        names.insert(T::schema().name());
      }(),
      ...);
  return names;
}

std::set<std::string> as_set(const std::vector<std::string>& v) {
  return {v.begin(), v.end()};
}

TEST(CatalogueBindings, Materials) {
  const auto names = check_types<LinearElastic, VonMises, Tresca, MohrCoulomb, DruckerPrager>();
  EXPECT_EQ(names, as_set(builtin_materials().names()));
}

TEST(CatalogueBindings, InterfaceLaws) {
  const auto names =
      check_types<contact::Rccm, contact::CoulombSignorini, contact::PerfectBonding>();
  EXPECT_EQ(names, as_set(contact::builtin_interface_laws().names()));
}

TEST(CatalogueBindings, SolverOptions) {
  std::set<std::string> names;
  for (const auto& schema : contact::contact_solver_schemas()) {
    expect_every_key_bound(schema);
    names.insert(schema.name());
  }
  EXPECT_EQ(names, as_set(contact::contact_solvers().names()));
  expect_every_key_bound(LinearSolver::schema());
  expect_struct_defaults_match(LinearSolver::schema());
}

// The pile app's own sections, built only from its reader.
TEST(CatalogueBindings, PileSections) {
  const auto check = [](const auto& schema) {
    expect_every_key_bound(schema);
    expect_struct_defaults_match(schema);
  };
  check(pile::geometry_schema());
  check(pile::mesh_schema());
  check(pile::geostatic_schema());
  check(pile::installation_schema());
  check(pile::pullout_schema());
}

// The general input's stage keys and its `control` mapping.
TEST(CatalogueBindings, StageSections) {
  expect_every_key_bound(stage_schema());
  expect_struct_defaults_match(stage_schema());
  expect_every_key_bound(control_schema());
  expect_struct_defaults_match(control_schema());
}

// The keys the pile's pullout shares with the general input's stages are declared once: the
// same type, default, range, units and doc, to the letter.
TEST(CatalogueBindings, PulloutSharesTheStageKeys) {
  const auto stage = stage_schema();
  const auto control = control_schema();
  const auto pullout = pile::pullout_schema();
  const std::vector<std::pair<const ParamSchema*, std::string>> shared = {
      {&stage, "duration"},
      {&stage, "energy_tolerance"},
      {&control, "type"},
      {&control, "dissipation_step"},
      {&control, "max_increments"}};
  for (const auto& [schema, key] : shared) {
    const ParamSpec* general = schema->find(key);
    const ParamSpec* pile = pullout.find(key == "type" ? "control" : key);
    ASSERT_NE(general, nullptr) << key;
    ASSERT_NE(pile, nullptr) << key;
    EXPECT_EQ(pile->summary(), general->summary()) << key;
    EXPECT_EQ(pile->range_reason, general->range_reason) << key;
  }
  EXPECT_EQ(stage.find("energy_tolerance")->summary().rfind("real, default 1e-06, [0, 1): ", 0),
            0u);
}

} // namespace
} // namespace bipot
