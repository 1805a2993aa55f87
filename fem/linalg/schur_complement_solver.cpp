#include "fem/linalg/schur_complement_solver.hpp"

#include "fem/linalg/detail/distributed_schur.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/sparse_matrix.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace bipot {

struct SchurComplementSolver::Impl {
  detail::DistributedSchur direct;
};

SchurComplementSolver::SchurComplementSolver() : impl_(std::make_unique<Impl>()) {}
SchurComplementSolver::~SchurComplementSolver() = default;

void SchurComplementSolver::factorize(const SparseMatrix& A, const std::vector<Index>& schur_dofs,
                                      bool symmetric) {
  const auto t0 = std::chrono::steady_clock::now();
  dofs_ = schur_dofs;
  std::sort(dofs_.begin(), dofs_.end());
  const std::vector<long long> vars(dofs_.begin(), dofs_.end());
  schur_.resize(0, 0); // the old S is not needed while MUMPS factorises (its peak)
  impl_->direct.factorize(A.impl_->matrix, vars, symmetric, schur_);
  const Index m = static_cast<Index>(dofs_.size());
  // Relative asymmetry max |S_ij − S_ji| / max |S_ij|, by columns of the lower triangle.
  double worst = 0, largest = 0;
  for (Index j = 0; j < m; ++j)
    for (Index i = j; i < m; ++i) {
      worst = std::max(worst, std::abs(schur_(i, j) - schur_(j, i)));
      largest = std::max(largest, std::abs(schur_(i, j)));
    }
  asymmetry_ = largest > 0 ? worst / largest : 0.0;
  setup_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void SchurComplementSolver::set_factor_directory(const std::string& directory) {
  impl_->direct.set_factor_directory(directory);
}

Eigen::VectorXd SchurComplementSolver::reduce(const DistributedVector& b) {
  const std::vector<double> c = impl_->direct.reduce(b.owned_values());
  return Eigen::Map<const Eigen::VectorXd>(c.data(), static_cast<Index>(c.size()));
}

void SchurComplementSolver::expand(const Eigen::VectorXd& x_schur, DistributedVector& x) {
  impl_->direct.expand(std::vector<double>(x_schur.data(), x_schur.data() + x_schur.size()),
                       x.owned_values());
}

} // namespace bipot
