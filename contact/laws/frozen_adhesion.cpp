#include "contact/laws/frozen_adhesion.hpp"

namespace bipot::contact {

double FrozenAdhesion::update_adhesion(double beta_old, const LocalVector& jump, double,
                                       LocalVector* dbeta_djump) const {
  if (dbeta_djump) *dbeta_djump = LocalVector::Zero(jump.size());
  return beta_old;
}

} // namespace bipot::contact
