#include "contact/interface/interface_frame.hpp"

#include <cassert>
#include <cmath>

namespace bipot::contact {

void complete_frame(const std::array<double, 3>& n, int dim, std::array<double, 3>& t1,
                    std::array<double, 3>& t2) {
  assert(dim == 2 || dim == 3);
  if (dim == 2) {
    t1 = {-n[1], n[0], 0.0};
    t2 = {0.0, 0.0, 0.0};
    return;
  }
  // The axis least aligned with n keeps e − (e·n) n far from zero (its norm is ≥ sqrt(2/3)).
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[k])) k = i;
  std::array<double, 3> t{0.0, 0.0, 0.0};
  t[k] = 1.0;
  for (int i = 0; i < 3; ++i)
    t[i] -= n[k] * n[i];
  const double len = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  for (double& v : t)
    v /= len;
  t1 = t;
  t2 = {n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]};
}

LocalVector to_local(const InterfacePair& pair, const double* global_vec, int dim) {
  assert(dim == 2 || dim == 3);
  const std::array<double, 3>* axes[3] = {&pair.normal, &pair.tangent1, &pair.tangent2};
  LocalVector local(dim);
  for (int j = 0; j < dim; ++j) {
    double s = 0.0;
    for (int i = 0; i < dim; ++i)
      s += (*axes[j])[i] * global_vec[i];
    local(j) = s;
  }
  return local;
}

void to_global(const InterfacePair& pair, const LocalVector& local, double* out, int dim) {
  assert((dim == 2 || dim == 3) && local.size() == dim);
  const std::array<double, 3>* axes[3] = {&pair.normal, &pair.tangent1, &pair.tangent2};
  for (int i = 0; i < dim; ++i) {
    double s = 0.0;
    for (int j = 0; j < dim; ++j)
      s += (*axes[j])[i] * local(j);
    out[i] = s;
  }
}

} // namespace bipot::contact
