#include "contact/laws/interface_law_registry.hpp"

#include "contact/laws/coulomb_signorini.hpp"
#include "contact/laws/perfect_bonding.hpp"
#include "contact/laws/rccm.hpp"

namespace bipot::contact {

namespace {
template <class T> void add(Registry<InterfaceLaw>& r) {
  r.add(T::schema(), [](const ParameterSet& p) { return std::make_unique<T>(p); });
}
} // namespace

void register_interface_laws(Registry<InterfaceLaw>& registry) {
  add<CoulombSignorini>(registry);
  add<PerfectBonding>(registry);
  add<Rccm>(registry);
}

Registry<InterfaceLaw> builtin_interface_laws() {
  Registry<InterfaceLaw> registry("interface law");
  register_interface_laws(registry);
  return registry;
}

} // namespace bipot::contact
