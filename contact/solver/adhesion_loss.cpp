#include "contact/solver/adhesion_loss.hpp"

#include <algorithm>

namespace bipot::contact {

AdhesionLoss adhesion_loss(double w, double beta_old, double drive_old, double beta_new,
                           double drive_new) {
  const double loss = beta_old - beta_new;
  if (loss == 0.0) return {};
  const double excess_old = std::max(drive_old - w, 0.0);
  const double excess_new = std::max(drive_new - w, 0.0);
  return {w * loss, 0.5 * (excess_old + excess_new) * loss};
}

} // namespace bipot::contact
