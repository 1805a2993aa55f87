#include "materials/material_registry.hpp"

#include "materials/drucker_prager.hpp"
#include "materials/linear_elastic.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/tresca.hpp"
#include "materials/von_mises.hpp"

namespace bipot {

void register_materials(Registry<Material>& registry) {
  registry.add<LinearElastic>();
  registry.add<VonMises>();
  registry.add<Tresca>();
  registry.add<MohrCoulomb>();
  registry.add<DruckerPrager>();
}

Registry<Material> builtin_materials() {
  Registry<Material> registry("material");
  register_materials(registry);
  return registry;
}

} // namespace bipot
