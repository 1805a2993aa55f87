#include "materials/material_registry.hpp"

#include "materials/drucker_prager.hpp"
#include "materials/linear_elastic.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/tresca.hpp"
#include "materials/von_mises.hpp"

namespace bipot {

namespace {
template <class T> void add(Registry<Material>& r) {
  r.add(T::schema(), [](const ParameterSet& p) { return std::make_unique<T>(p); });
}
} // namespace

void register_materials(Registry<Material>& registry) {
  add<LinearElastic>(registry);
  add<VonMises>(registry);
  add<Tresca>(registry);
  add<MohrCoulomb>(registry);
  add<DruckerPrager>(registry);
}

Registry<Material> builtin_materials() {
  Registry<Material> registry("material");
  register_materials(registry);
  return registry;
}

} // namespace bipot
