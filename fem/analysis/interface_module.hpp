#pragma once
/// What the FE core needs from the module that builds and enforces a model's interfaces: the
/// split mesh and the laws (build()), checks of the whole model, one InterfaceEnforcement per
/// interface and, for generalized_newton, the condensed interface equations. bipot's contact
/// module provides one (apps/catalogue/contact_module.cpp); build_model() keeps it in the
/// Model.

#include "fem/assembly/condensed_interface_system.hpp"
#include "fem/assembly/dof_map.hpp"
#include "fem/assembly/interface_enforcement.hpp"

#include <memory>
#include <string>
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

/// What a module keeps of a model it built (opaque to the FE core).
class InterfaceData {
public:
  virtual ~InterfaceData() = default;
};

class InterfaceModule {
public:
  virtual ~InterfaceModule() = default;
  /// Builds the interfaces of model.spec on model.mesh (splitting it where bodies may
  /// separate): model.interfaces, model.interface_data and model.contact_solver. Called by
  /// build_model() once the mesh and materials are checked. Throws InputError, each problem
  /// at the user's file:line:col.
  virtual void build(Model& model) const = 0;
  /// What only the whole built model shows (e.g. a condensed system too large), each problem
  /// at its place; empty if none.
  virtual std::vector<std::string> check(const Model& model) const = 0;
  /// Nodes the interfaces hold in place from the start (a body bonded to a rigid obstacle):
  /// no boundary condition or rigid body may move them, and they hold their body.
  virtual std::vector<Index> held_nodes(const Model& model) const = 0;
  /// The enforcements of `model`'s interfaces on its DOFs (they keep references to the model,
  /// `dofs` and `dist`). Throws InputError for a model it cannot enforce.
  virtual EnforcedInterfaces enforce(const Model& model, const DofMap& dofs,
                                     const DofDistribution& dist) const = 0;
};

} // namespace bipot
