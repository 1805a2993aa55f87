#include "contact/laws/perfect_bonding.hpp"

namespace bipot::contact {

ParamSchema PerfectBonding::schema() {
  return ParamSchema("perfect_bonding",
                     "perfectly bonded (tied) interface: zero jump, enforced exactly");
}

} // namespace bipot::contact
