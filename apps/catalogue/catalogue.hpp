#pragma once
/// What a model can be built from: the bulk materials, interface laws and contact solvers by
/// YAML name. Passed to the reader and to build_model(), never looked up globally, so a
/// project using an installed bipot adds its own law or material without editing bipot
/// (tests/install/consumer does exactly that).

#include "contact/laws/interface_law.hpp"
#include "contact/solver/contact_solver_options.hpp"
#include "fem/analysis/model.hpp"
#include "fem/core/material.hpp"
#include "fem/core/registry.hpp"
#include "fem/input/input_catalogue.hpp"

namespace bipot {

struct Catalogue {
  Registry<Material> materials{"material"};
  Registry<contact::InterfaceLaw> interface_laws{"interface law"};
  /// The contact algorithms are the toolkit's own (the contact module enforces them), so
  /// this one is fixed: its entries only turn validated options into ContactSolverOptions.
  const Registry<contact::ContactSolverOptions>& contact_solvers = contact::contact_solvers();

  operator InputCatalogue() const { return {materials, interface_laws, contact_solvers}; }
};

/// The model of `spec` with the catalogue's materials, its interfaces built and enforced by
/// the contact module over the catalogue's laws (contact_module.hpp). `catalogue` must know
/// every name `spec` uses (the one `spec` was read with).
Model build_model(const ProblemSpec& spec, const Catalogue& catalogue);

} // namespace bipot
