#pragma once
/// The registries the input reader validates against, handed in by the application.

#include "fem/core/registry.hpp"

namespace bipot {

/// Names and parameter schemas only: the reader checks `type:`/`law:` names and their
/// parameters without knowing the classes behind them, so fem/input depends on neither
/// materials/ nor contact/. An application builds a Catalogue (apps/catalogue/catalogue.hpp,
/// usually apps/catalogue's builtin_catalogue() plus its own entries), which converts to this.
struct InputCatalogue {
  const SchemaIndex& materials;
  const SchemaIndex& interface_laws;
  const SchemaIndex& contact_solvers;
};

} // namespace bipot
