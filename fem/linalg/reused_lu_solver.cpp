#include "fem/linalg/reused_lu_solver.hpp"

#include <unsupported/Eigen/IterativeSolvers>

namespace bipot {

namespace {

// Eigen's preconditioner concept around factors computed elsewhere: GMRES calls compute() on
// the new matrix, which must not refactorise it (that is the point).
struct EarlierFactors {
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = Eigen::Index;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic };
  const Eigen::PartialPivLU<Eigen::MatrixXd>* lu = nullptr;

  EarlierFactors() = default;
  template <class M> explicit EarlierFactors(const M&) {}
  template <class M> EarlierFactors& analyzePattern(const M&) { return *this; }
  template <class M> EarlierFactors& factorize(const M&) { return *this; }
  template <class M> EarlierFactors& compute(const M&) { return *this; }
  template <class R> Eigen::VectorXd solve(const Eigen::MatrixBase<R>& b) const {
    return lu->solve(b);
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }
};

} // namespace

Eigen::VectorXd ReusedLuSolver::factorize_and_solve(const Eigen::MatrixXd& J,
                                                    const Eigen::VectorXd& b) {
  lu_.compute(J);
  factorized_ = true;
  ++factorizations_;
  last_iterations_ = 0;
  return lu_.solve(b);
}

Eigen::VectorXd ReusedLuSolver::solve(const Eigen::MatrixXd& J, const Eigen::VectorXd& b) {
  const double b_norm = b.norm();
  if (b_norm == 0.0) return Eigen::VectorXd::Zero(b.size());
  if (!factorized_ || lu_.rows() != J.rows()) return factorize_and_solve(J, b);
  Eigen::GMRES<Eigen::MatrixXd, EarlierFactors> gmres;
  gmres.set_restart(max_iterations_);
  gmres.setMaxIterations(max_iterations_);
  gmres.setTolerance(tolerance_);
  gmres.compute(J);
  gmres.preconditioner().lu = &lu_;
  // Eigen's GMRES stops on the preconditioned residual; the true one (one product to check)
  // is larger by up to the conditioning of the earlier factors: 1e-12 became 1e-10 to 1e-8 on
  // the pile's matrices. A GMRES solve of the true residual (iterative refinement) recovers
  // what was lost; a residual that does not shrink means the factors are too far off.
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size()), r = b;
  last_iterations_ = 0;
  for (int pass = 0; pass < 3; ++pass) {
    x += gmres.solve(r);
    last_iterations_ += static_cast<int>(gmres.iterations());
    if (gmres.info() != Eigen::Success || !x.allFinite()) break;
    r = b - J * x;
    if (r.norm() <= accept_ * b_norm) {
      iterations_ += last_iterations_;
      return x;
    }
  }
  iterations_ += last_iterations_;
  return factorize_and_solve(J, b);
}

} // namespace bipot
