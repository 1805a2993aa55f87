#pragma once
/// The registry of interface laws by YAML name.

#include "contact/laws/interface_law.hpp"
#include "fem/core/registry.hpp"

namespace bipot::contact {

/// Adds every built-in interface law: one line per law. To add one, write its header/source
/// pair, add its line here, a unit test and a page in docs/laws/.
void register_interface_laws(Registry<InterfaceLaw>& registry);

/// The registry filled by register_interface_laws() (what = "interface law"), built on first
/// use.
const Registry<InterfaceLaw>& interface_laws();

} // namespace bipot::contact
