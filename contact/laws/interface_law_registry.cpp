#include "contact/laws/interface_law_registry.hpp"

#include "contact/laws/coulomb_signorini.hpp"
#include "contact/laws/perfect_bonding.hpp"
#include "contact/laws/rccm.hpp"

namespace bipot::contact {

void register_interface_laws(Registry<InterfaceLaw>& registry) {
  registry.add<CoulombSignorini>();
  registry.add<PerfectBonding>();
  registry.add<Rccm>();
}

Registry<InterfaceLaw> builtin_interface_laws() {
  Registry<InterfaceLaw> registry("interface law");
  register_interface_laws(registry);
  return registry;
}

} // namespace bipot::contact
