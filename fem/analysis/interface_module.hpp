#pragma once
/// What the analysis needs from the module that enforces a model's interfaces: one
/// InterfaceEnforcement per interface and, for generalized_newton, the condensed interface
/// equations. The contact module provides one (apps/catalogue/contact_module.cpp); a Catalogue
/// hands it to build_model(), which keeps it in the Model.

#include "fem/assembly/condensed_interface_system.hpp"
#include "fem/assembly/dof_map.hpp"
#include "fem/assembly/interface_enforcement.hpp"

#include <memory>
#include <vector>

namespace bipot {

class DofDistribution;
struct Model;

struct EnforcedInterfaces {
  /// One per interface of the model, in its order.
  std::vector<std::unique_ptr<InterfaceEnforcement>> interfaces;
  /// The condensed equations of those that act on the system, when the model's nonlinear
  /// solver is the exact generalized Newton and some interface acts; else null.
  std::unique_ptr<CondensedInterfaceSystem> condensed;
};

class InterfaceModule {
public:
  virtual ~InterfaceModule() = default;
  /// The enforcements of `model`'s interfaces on its DOFs (they keep references to the model,
  /// `dofs` and `dist`). Throws InputError for a model it cannot enforce.
  virtual EnforcedInterfaces enforce(const Model& model, const DofMap& dofs,
                                     const DofDistribution& dist) const = 0;
};

} // namespace bipot
