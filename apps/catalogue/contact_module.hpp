#pragma once
/// bipot's interface module: the contact module wired to the FE core's Model.

#include "contact/laws/interface_law.hpp"
#include "fem/analysis/interface_module.hpp"
#include "fem/analysis/model.hpp"
#include "fem/core/registry.hpp"

#include <memory>

namespace bipot {

/// Builds interfaces with `laws` (copied): interfaces bonded in every stage keep shared nodes,
/// the others are split and paired (contact::split_interfaces). Interfaces whose bodies share
/// nodes are tied exactly (contact::TiedInterface); the others are enforced pair by pair
/// through their law (contact::InterfaceAssembler), with the law each stage puts in force.
/// With generalized_newton, the condensed equations are contact::InterfaceNewtonSystem over
/// the latter.
std::shared_ptr<const InterfaceModule> contact_module(Registry<contact::InterfaceLaw> laws);

/// The law interface `k` of a model built by contact_module() starts with.
const contact::InterfaceLaw& interface_law(const Model& model, std::size_t k);

} // namespace bipot
