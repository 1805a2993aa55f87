#pragma once
/// The registry of bulk materials by YAML name.

#include "fem/core/registry.hpp"
#include "materials/material.hpp"

namespace bipot {

/// Adds every built-in material: one line per material. To add one, write its header/source
/// pair, add its line here, a unit test and a docs page (docs/adding_a_material.md).
void register_materials(Registry<Material>& registry);

/// The registry filled by register_materials(), built on first use.
const Registry<Material>& materials();

} // namespace bipot
