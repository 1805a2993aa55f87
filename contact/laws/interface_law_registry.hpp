#pragma once
/// The registry of interface laws by YAML name.

#include "contact/laws/interface_law.hpp"
#include "fem/core/registry.hpp"

namespace bipot::contact {

/// Adds every built-in interface law: one line per law. To add one to bipot, write its
/// header/source pair, add its line here, a unit test and a page in docs/laws/; a project
/// using an installed bipot adds it to its own catalogue instead
/// (apps/catalogue/builtin_catalogue.hpp).
void register_interface_laws(Registry<InterfaceLaw>& registry);

/// A fresh registry ("interface law") with the built-in laws.
Registry<InterfaceLaw> builtin_interface_laws();

} // namespace bipot::contact
