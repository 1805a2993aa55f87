// Registry and parameter schemas of the interface laws: names, error messages, and the docs
// tables (generated from the same schemas, so they cannot drift).
#include "contact/laws/coulomb_signorini.hpp"
#include "contact/laws/interface_law_registry.hpp"
#include "contact/laws/perfect_bonding.hpp"
#include "contact/laws/rccm.hpp"
#include "fem/core/error.hpp"
#include "local_test_utils.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace bipot::contact {
namespace {

ParameterSet rccm_params() {
  ParameterSet p;
  p.set("normal_stiffness", 1.0e6);
  p.set("tangential_stiffness", 5.0e5);
  p.set("decohesion_energy", 0.05);
  p.set("friction_coefficient", 0.5);
  return p;
}

/// The message of the InputError thrown by creating `name` with `params` ("" if none).
std::string creation_error(const std::string& name, const ParameterSet& params) {
  try {
    builtin_interface_laws().create(name, params);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(InterfaceLawRegistry, Names) {
  EXPECT_EQ(builtin_interface_laws().names(),
            (std::vector<std::string>{"coulomb_signorini", "perfect_bonding", "rccm"}));
  EXPECT_EQ(builtin_interface_laws().what(), "interface law");
}

TEST(InterfaceLawRegistry, CreatesEachLawWithDefaults) {
  const auto rccm = builtin_interface_laws().create("rccm", rccm_params());
  EXPECT_EQ(rccm->name(), "rccm");
  EXPECT_FALSE(rccm->is_tied());
  EXPECT_EQ(rccm->initial_adhesion(), 1.0);  // default β0
  EXPECT_EQ(rccm->stiffness_scale(), 1.0e6); // max(C_n, C_t)
  EXPECT_EQ(rccm->friction_coefficient(0.0), 0.5);
  const auto& r = dynamic_cast<const Rccm&>(*rccm);
  EXPECT_EQ(r.adhesion_viscosity(), 0.0); // default: quasi-static
  EXPECT_EQ(r.tangential_stiffness(), 5.0e5);

  const auto cs = builtin_interface_laws().create("coulomb_signorini", ParameterSet{});
  EXPECT_EQ(cs->name(), "coulomb_signorini");
  EXPECT_EQ(cs->friction_coefficient(0.0), 0.0); // default: frictionless
  EXPECT_EQ(cs->initial_adhesion(), 0.0);
  EXPECT_EQ(cs->stiffness_scale(), 0.0);

  const auto tied = builtin_interface_laws().create("perfect_bonding", ParameterSet{});
  EXPECT_EQ(tied->name(), "perfect_bonding");
  EXPECT_TRUE(tied->is_tied());
  // On split pairs (bonded in some stages only) a tied law is the equality multiplier of
  // evaluate_tie(): r_new = r − ρ (jump − old.jump), no cone, the traction is r_new, β = 1.
  InterfaceState old = initial_state(*tied, 2);
  old.jump << 1e-3, -2e-3;
  LocalVector jump(2), r_in(2);
  jump << 1.5e-3, -1e-3;
  r_in << 40.0, -250.0; // outside any cone: a tie takes any traction
  const double rho = 1e4;
  InterfaceResponseDerivatives d;
  const InterfaceResponse out = evaluate(*tied, old, jump, r_in, 1.0, rho, &d);
  EXPECT_EQ(out.beta, 1.0);
  EXPECT_EQ(out.status, ContactStatus::Stick);
  EXPECT_NEAR(out.traction(0), 40.0 - rho * 0.5e-3, 1e-12);
  EXPECT_NEAR(out.traction(1), -250.0 - rho * 1e-3, 1e-12);
  EXPECT_EQ(out.r, out.traction);
  // Its fixed point r_new = r is the held jump.
  EXPECT_EQ(evaluate(*tied, old, old.jump, r_in, 1.0, rho).r, r_in);
  // Generalized derivatives: ∂r/∂jump = −ρ I, ∂r/∂r = I (linear map, exact).
  EXPECT_EQ(d.dt_djump, (-rho * LocalMatrix::Identity(2, 2)).eval());
  EXPECT_EQ(d.dr_dr, LocalMatrix::Identity(2, 2));
}

TEST(InterfaceLawRegistry, OutOfRangeValuesNameKeyAndInterval) {
  struct Case {
    std::string key;
    double value;
    std::string interval;
  };
  const std::vector<Case> cases = {{"normal_stiffness", -1.0, "(0, inf) kN/m^3"},
                                   {"decohesion_energy", 0.0, "(0, inf) kJ/m^2"},
                                   {"friction_coefficient", -0.1, "[0, inf)"},
                                   {"initial_adhesion", 1.5, "[0, 1]"},
                                   {"adhesion_viscosity", -1.0, "[0, inf) kN*s/m"}};
  for (const auto& c : cases) {
    ParameterSet p = rccm_params();
    p.set(c.key, c.value);
    const std::string msg = creation_error("rccm", p);
    EXPECT_TRUE(contains(msg, "rccm." + c.key + ": ")) << msg;
    EXPECT_TRUE(contains(msg, "out of range " + c.interval)) << msg;
  }
  // The direct constructor reports the same way.
  try {
    Rccm({1e6, 1e6, 0.05, 0.0, 0.0, 1.5});
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "rccm.initial_adhesion: value 1.5 is out of range [0, 1]");
  }
  try {
    CoulombSignorini({-0.1});
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "coulomb_signorini.friction_coefficient: value -0.1 is out of range [0, inf)");
  }
}

TEST(InterfaceLawRegistry, UnknownNameListsRegisteredLaws) {
  const std::string msg = creation_error("rcm", ParameterSet{});
  EXPECT_EQ(msg, "unknown interface law 'rcm' (did you mean 'rccm'?); registered: "
                 "coulomb_signorini, perfect_bonding, rccm");
}

TEST(InterfaceLawRegistry, MisspeltAndMissingKeys) {
  ParameterSet p = rccm_params();
  p.set("normal_stifness", 1.0);
  std::string msg = creation_error("rccm", p);
  EXPECT_TRUE(contains(msg, "rccm.normal_stifness: unknown key for 'rccm' (did you mean "
                            "'normal_stiffness'?)"))
      << msg;
  ParameterSet missing;
  missing.set("normal_stiffness", 1.0e6);
  msg = creation_error("rccm", missing);
  EXPECT_TRUE(contains(msg, "rccm.tangential_stiffness: missing required key")) << msg;
  EXPECT_TRUE(contains(msg, "rccm.decohesion_energy: missing required key")) << msg;
  ParameterSet extra;
  extra.set("friction_coefficient", 0.3);
  msg = creation_error("perfect_bonding", extra);
  EXPECT_TRUE(contains(msg, "allowed keys: none")) << msg;
}

std::string read_doc(const std::string& name) {
  std::ifstream in(std::string(BIPOT_SOURCE_DIR) + "/docs/laws/" + name + ".md");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(InterfaceLawRegistry, DocsTablesMatchSchemas) {
  for (const auto& name : builtin_interface_laws().names()) {
    const std::string table = builtin_interface_laws().schema(name).markdown_table();
    EXPECT_TRUE(contains(read_doc(name), table)) << "docs/laws/" << name << ".md must contain:\n"
                                                 << table;
  }
}

} // namespace
} // namespace bipot::contact
