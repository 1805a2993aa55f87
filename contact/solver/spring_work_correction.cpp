#include "contact/solver/spring_work_correction.hpp"

namespace bipot::contact {

SpringPath spring_path(const SpringHistory& h) {
  const bool f1 = h.beta[0] > h.beta[1], f2 = h.beta[1] > h.beta[2], f3 = h.beta[2] > h.beta[3];
  if (!f1 && !f2 && !f3) return SpringPath::Steady;
  return f1 && f2 && f3 && h.beta[3] > 0 ? SpringPath::Softening : SpringPath::Kinked;
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
