#include "contact/solver/spring_work_correction.hpp"

namespace bipot::contact {

int spring_regime(double beta_old, double beta_new, int status) {
  // β reaching 0 ends the springs within the step: a regime of its own, so that the steps
  // around it are kinked.
  const int beta_code = beta_new < beta_old ? (beta_new > 0 ? 1 : 2) : 0;
  return 3 * status + beta_code;
}

SpringPath spring_path(const SpringHistory& h) {
  if (h.regime_steps < regime_steps_needed) return SpringPath::Kinked;
  return h.softening ? SpringPath::Softening : SpringPath::Steady;
}

double spring_work_correction(const ThreePointRule& rule, const SpringHistory& h) {
  if (!rule.three_point || spring_path(h) != SpringPath::Softening) return 0.0;
  double sum = 0;
  for (Eigen::Index c = 0; c < h.g[2].size(); ++c) {
    const double f[3] = {-h.a[0](c), -h.a[1](c), -h.a[2](c)};
    const double u[3] = {h.g[0](c), h.g[1](c), h.g[2](c)};
    sum += rule.correction(f, u);
  }
  return sum;
}

} // namespace bipot::contact
