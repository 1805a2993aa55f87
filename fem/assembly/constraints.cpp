#include "fem/assembly/constraints.hpp"

namespace bipot {

double Constraints::value(Index dof) const {
  auto it = values_.find(dof);
  return it == values_.end() ? 0.0 : it->second;
}

void Constraints::condense(const Index* dofs, int n, double* K, double* R) const {
  if (values_.empty()) return;
  for (int c = 0; c < n; ++c) {
    auto it = values_.find(dofs[c]);
    if (it == values_.end()) continue;
    const double du = it->second;
    double diag = K[c * n + c];
    // A cell with no stiffness on this DOF still must not make the global diagonal zero.
    if (!(diag > 0)) diag = 1.0;
    for (int b = 0; b < n; ++b) {
      if (b == c) continue;
      R[b] -= K[b * n + c] * du;
      K[b * n + c] = 0.0;
      K[c * n + b] = 0.0;
    }
    K[c * n + c] = diag;
    R[c] = diag * du;
  }
}

void Constraints::condense(const Index* dofs, int n, double* R) const {
  if (values_.empty()) return;
  for (int c = 0; c < n; ++c)
    if (values_.count(dofs[c])) R[c] = 0.0;
}

} // namespace bipot
