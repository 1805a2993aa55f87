#include "apps/catalogue/builtin_catalogue.hpp"

#include "contact/laws/interface_law_registry.hpp"
#include "materials/material_registry.hpp"

namespace bipot {

Catalogue builtin_catalogue() {
  Catalogue catalogue;
  catalogue.materials = builtin_materials();
  catalogue.interface_laws = contact::builtin_interface_laws();
  return catalogue;
}

} // namespace bipot
