#pragma once
/// bipot's interface module: the contact module's enforcements wired to a Model.

#include "fem/analysis/interface_module.hpp"

#include <memory>

namespace bipot {

/// Interfaces whose bodies share nodes are tied exactly (contact::TiedInterface); the others
/// are enforced pair by pair through their law (contact::InterfaceAssembler), with the law
/// each stage puts in force. With generalized_newton, the condensed equations are
/// contact::InterfaceNewtonSystem over the latter.
std::shared_ptr<const InterfaceModule> contact_module();

} // namespace bipot
