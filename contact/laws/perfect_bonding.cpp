#include "contact/laws/perfect_bonding.hpp"

namespace bipot::contact {

ParamSchemaOf<PerfectBonding::Parameters> PerfectBonding::schema() {
  return ParamSchemaOf<Parameters>(
      "perfect_bonding", "perfectly bonded (tied) interface: zero jump, enforced exactly");
}

} // namespace bipot::contact
