#include "fem/linalg/reused_lu_solver.hpp"

#include "fem/linalg/communicator.hpp"

#include <unsupported/Eigen/IterativeSolvers>

#include <algorithm>
#include <type_traits>

namespace bipot::detail {
class CondensedOperator;
}

// Eigen's matrix-free protocol (its "matrix-free solvers" example): GMRES sees a
// CondensedNewtonMatrix as a sparse-shaped operator whose product with a vector is −S x + P x.
namespace Eigen::internal {
template <>
struct traits<bipot::detail::CondensedOperator> : public traits<Eigen::SparseMatrix<double>> {};
} // namespace Eigen::internal

namespace bipot::detail {
class CondensedOperator : public Eigen::EigenBase<CondensedOperator> {
public:
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum {
    ColsAtCompileTime = Eigen::Dynamic,
    MaxColsAtCompileTime = Eigen::Dynamic,
    IsRowMajor = false
  };
  explicit CondensedOperator(const CondensedNewtonMatrix& J) : J(&J) {}
  Eigen::Index rows() const { return J->rows(); }
  Eigen::Index cols() const { return J->cols(); }
  template <class Rhs>
  Eigen::Product<CondensedOperator, Rhs, Eigen::AliasFreeProduct>
  operator*(const Eigen::MatrixBase<Rhs>& x) const {
    return Eigen::Product<CondensedOperator, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }
  const CondensedNewtonMatrix* J;
};
} // namespace bipot::detail

namespace Eigen::internal {
template <class Rhs>
struct generic_product_impl<bipot::detail::CondensedOperator, Rhs, SparseShape, DenseShape,
                            GemvProduct>
    : generic_product_impl_base<bipot::detail::CondensedOperator, Rhs,
                                generic_product_impl<bipot::detail::CondensedOperator, Rhs>> {
  template <class Dst>
  static void scaleAndAddTo(Dst& dst, const bipot::detail::CondensedOperator& lhs, const Rhs& rhs,
                            const double& alpha) {
    lhs.J->add_product(dst, rhs, alpha);
  }
};
} // namespace Eigen::internal

namespace bipot {

namespace {

using Factors = Eigen::PartialPivLU<Eigen::Ref<Eigen::MatrixXd>>;
using SingleFactors = Eigen::PartialPivLU<Eigen::Ref<Eigen::MatrixXf>>;

// Eigen's preconditioner concept around factors computed elsewhere: GMRES calls compute() on
// the new matrix, which must not refactorise it (that is the point).
struct EarlierFactors {
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = Eigen::Index;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic };
  const Factors* lu = nullptr;
  const SingleFactors* lu_single = nullptr; // used if set
  // The substitutions shared by the ranks (several ranks, J in operator form), if set.
  const SplitTriangularSolve<double>* split = nullptr;
  const SplitTriangularSolve<float>* split_single = nullptr;

  EarlierFactors() = default;
  template <class M> explicit EarlierFactors(const M&) {}
  template <class M> EarlierFactors& analyzePattern(const M&) { return *this; }
  template <class M> EarlierFactors& factorize(const M&) { return *this; }
  template <class M> EarlierFactors& compute(const M&) { return *this; }
  template <class R> Eigen::VectorXd solve(const Eigen::MatrixBase<R>& b) const {
    if (lu_single && split_single) {
      Eigen::VectorXf x = lu_single->permutationP() * b.template cast<float>();
      split_single->solve_in_place(x);
      return x.cast<double>();
    }
    if (lu_single) return lu_single->solve(b.template cast<float>()).template cast<double>();
    if (split) {
      Eigen::VectorXd x = lu->permutationP() * b;
      split->solve_in_place(x);
      return x;
    }
    return lu->solve(b);
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }
};

// What GMRES iterates on: the dense matrix itself, or the operator around the condensed one.
const Eigen::MatrixXd& gmres_matrix(const Eigen::MatrixXd& J) {
  return J;
}
detail::CondensedOperator gmres_matrix(const CondensedNewtonMatrix& J) {
  return detail::CondensedOperator(J);
}
template <class Scalar>
void make_dense(const Eigen::MatrixXd& J,
                Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& out) {
  out = J.cast<Scalar>();
}
template <class Scalar>
void make_dense(const CondensedNewtonMatrix& J,
                Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& out) {
  J.to_dense(out);
}

} // namespace

template <class Matrix> void ReusedLuSolver::factorize(const Matrix& J, bool single) {
  // The LU objects refer to the arrays, which may be reallocated; only one precision is kept.
  lu_.reset();
  lu_single_.reset();
  split_.reset();
  split_single_.reset();
  // J in operator form is what the ranks solve together (generalized_newton): its products
  // are collective already, so the substitutions can be too. A dense J may be a rank's own.
  const bool shared = std::is_same_v<Matrix, CondensedNewtonMatrix> && mpi_size() > 1;
  if (single) {
    factors_.resize(0, 0);
    make_dense(J, factors_single_);
    lu_single_ = std::make_unique<SingleFactors>(factors_single_);
    if (shared) split_single_ = std::make_unique<SplitTriangularSolve<float>>(factors_single_);
  } else {
    factors_single_.resize(0, 0);
    make_dense(J, factors_);
    lu_ = std::make_unique<Factors>(factors_);
    if (shared) split_ = std::make_unique<SplitTriangularSolve<double>>(factors_);
  }
  factor_rows_ = J.rows();
  factorized_ = true;
  iterations_on_factors_ = 0;
  ++factorizations_;
  last_iterations_ = 0; // a solve's count: the iterations on the factors it ends with
}

void ReusedLuSolver::reset() {
  // The LU objects refer to the arrays: they go first.
  lu_.reset();
  lu_single_.reset();
  split_.reset();
  split_single_.reset();
  factors_.resize(0, 0);
  factors_single_.resize(0, 0);
  factorized_ = false;
}

Eigen::VectorXd ReusedLuSolver::solve(const Eigen::MatrixXd& J, const Eigen::VectorXd& b,
                                      double accept) {
  return solve_any(J, b, accept);
}

Eigen::VectorXd ReusedLuSolver::solve(const CondensedNewtonMatrix& J, const Eigen::VectorXd& b,
                                      double accept) {
  return solve_any(J, b, accept);
}

template <class Matrix>
Eigen::VectorXd ReusedLuSolver::solve_any(const Matrix& J, const Eigen::VectorXd& b,
                                          double accept) {
  accept = std::max(accept, accept_);
  last_iterations_ = 0;
  if (b.norm() == 0.0) return Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd x;
  // Large factors that have cost refactor_after × n GMRES iterations are renewed even though
  // GMRES still converges on them: iterations grow as the matrix drifts from them (a
  // debonding front moving through the pairs).
  if (factorized_ && J.rows() >= renew_from_rows &&
      iterations_on_factors_ > refactor_after * static_cast<double>(J.rows()))
    factorized_ = false;
  if (factorized_ && factor_rows_ == J.rows() && refine(J, b, accept, x)) {
    iterations_on_factors_ += last_iterations_;
    return x;
  }
  // No factors, or too far off: factorise J. Double-precision factors solve directly;
  // single-precision ones through GMRES, and if even that fails J is factorised in double.
  if (single_) {
    factorize(J, true);
    if (refine(J, b, accept, x)) return x;
  }
  factorize(J, false);
  return lu_->solve(b);
}

template <class Matrix>
bool ReusedLuSolver::refine(const Matrix& J, const Eigen::VectorXd& b, double accept,
                            Eigen::VectorXd& x) {
  const double b_norm = b.norm();
  const auto op = gmres_matrix(J);
  using Op = std::decay_t<decltype(op)>;
  Eigen::GMRES<Op, EarlierFactors> gmres;
  gmres.set_restart(max_iterations_);
  gmres.compute(op);
  gmres.preconditioner().lu = lu_.get();
  gmres.preconditioner().lu_single = lu_single_.get();
  // Shared substitutions only where the products are shared (a dense J may be one rank's).
  if constexpr (std::is_same_v<Matrix, CondensedNewtonMatrix>) {
    gmres.preconditioner().split = split_.get();
    gmres.preconditioner().split_single = split_single_.get();
  }
  // Eigen's GMRES stops on the preconditioned residual; the true one (one product to check)
  // is larger by up to the conditioning of the earlier factors: 1e-12 became 1e-10 to 1e-8 on
  // the pile's matrices. A GMRES solve of the true residual (iterative refinement) recovers
  // what was lost; a residual that does not shrink means the factors are too far off.
  // The first pass aims at the tight acceptance within `cheap_iterations`: a matrix close to
  // the factorised one (a few pairs changed) is solved exactly, as a direct solver would, and
  // Newton keeps its finite termination on piecewise-linear problems. Past that the solve is
  // expensive, and `accept` (the caller's forcing term) is enough.
  x = Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd r = b;
  const bool loose = accept > accept_;
  bool expensive = false; // the first pass ran out of its cheap iterations
  bool met = false;
  double last_residual = b_norm;
  for (int pass = 0; pass < (loose ? 4 : 3); ++pass) {
    const bool first = loose && pass == 0;
    gmres.setTolerance(expensive ? std::max(tolerance_, 0.1 * accept) : tolerance_);
    gmres.setMaxIterations(first ? std::min(cheap_iterations, max_iterations_) : max_iterations_);
    x += gmres.solve(r);
    last_iterations_ += static_cast<int>(gmres.iterations());
    if (!x.allFinite()) break;
    const bool stopped = gmres.info() != Eigen::Success;
    if (stopped && !first) break; // out of iterations: the factors are too far off
    if (stopped) expensive = true;
    r = b - J * x;
    const double residual = r.norm();
    // A pass that gains less than 10x has reached the floor of J's conditioning: the tight
    // acceptance is out of reach of any factors (double ones give the same floor), and the
    // caller's forcing term is what Newton needs. Without this, fresh single-precision
    // factors stalling at 3e-10 against 1e-11 were thrown away for double ones, twice the
    // memory (the pile at 936k DOFs: n = 4628, 82 -> 164 MiB at the run's peak).
    const bool stalled = pass > 0 && residual > 0.1 * last_residual;
    last_residual = residual;
    if (residual <= accept_ * b_norm || ((expensive || stalled) && residual <= accept * b_norm)) {
      met = true;
      break;
    }
  }
  iterations_ += last_iterations_;
  return met;
}

} // namespace bipot
