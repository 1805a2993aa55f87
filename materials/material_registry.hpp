#pragma once
/// The registry of bulk materials by YAML name.

#include "fem/core/material.hpp"
#include "fem/core/registry.hpp"

namespace bipot {

/// Adds every built-in material: one line per material. To add one to bipot, write its
/// header/source pair, add its line here, a unit test and a docs page
/// (docs/adding_a_material.md); a project using an installed bipot adds it to its own
/// catalogue instead (apps/catalogue/builtin_catalogue.hpp).
void register_materials(Registry<Material>& registry);

/// A fresh registry ("material") with the built-in materials.
Registry<Material> builtin_materials();

} // namespace bipot
