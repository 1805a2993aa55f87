#pragma once
/// What a model can be built from: the bulk materials, interface laws and contact solvers by
/// YAML name. Passed to the reader and to build_model(), never looked up globally, so a
/// project using an installed bipot adds its own law or material without editing bipot
/// (tests/install/consumer does exactly that).

#include "contact/laws/interface_law.hpp"
#include "contact/solver/contact_solver_options.hpp"
#include "fem/analysis/interface_module.hpp"
#include "fem/core/material.hpp"
#include "fem/core/registry.hpp"
#include "fem/input/input_catalogue.hpp"

#include <memory>

namespace bipot {

struct Catalogue {
  Registry<Material> materials{"material"};
  Registry<contact::InterfaceLaw> interface_laws{"interface law"};
  /// The contact algorithms are the toolkit's own (fem/analysis drives them by type), so
  /// this one is fixed: its entries only turn validated options into ContactSolverOptions.
  const Registry<contact::ContactSolverOptions>& contact_solvers = contact::contact_solvers();
  /// Enforces the interfaces of the models built from this catalogue (the built-in one:
  /// apps/catalogue/contact_module.cpp).
  std::shared_ptr<const InterfaceModule> interface_module;

  operator InputCatalogue() const { return {materials, interface_laws, contact_solvers}; }
};

} // namespace bipot
