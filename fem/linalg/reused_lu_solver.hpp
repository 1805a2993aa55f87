#pragma once
/// Dense solves for a sequence of matrices that differ from one another in a few rows: the
/// Newton matrices of generalized_newton, where only the pairs that changed status (stick,
/// slip, open) or whose β moved change their rows between iterations and increments.

#include "fem/linalg/condensed_newton_matrix.hpp"
#include "fem/linalg/split_triangular_solve.hpp"

#include <Eigen/Dense>

#include <memory>

namespace bipot {

/// Solves J x = b by GMRES (Eigen's) preconditioned with the LU factors of an earlier J. If J
/// differs from the factorised matrix by a matrix of rank k, GMRES converges in about k + 1
/// iterations, each a matrix–vector product and a pair of triangular solves (O(n²)), against
/// (2/3) n³ for a new factorisation: at n = 4800 one LU costs as much as several hundred
/// iterations. Eigen's GMRES stops on the preconditioned residual, so the true residual is
/// checked and, if above `accept` relative to ‖b‖, GMRES solves for it again (iterative
/// refinement, up to three passes). J is factorised afresh when there are no factors yet or
/// when that fails (GMRES not converged in `max_iterations`, or the residual not shrinking:
/// the factors are too far off) or when the solves on them have taken refactor_after × n
/// iterations; the factors are then kept for the next solves.
///
/// With several MPI ranks and J in operator form (CondensedNewtonMatrix, whose products are
/// shared by the ranks) the preconditioner's substitutions are shared too
/// (SplitTriangularSolve); solve() is then collective. The factorisation stays on every rank.
///
/// With single-precision factors (set_single_precision_factors) the preconditioner streams
/// half the bytes and the factorisation is about twice as fast; GMRES, the products with J
/// and the acceptance test stay in double, so the solution meets the same tolerances (a
/// freshly factorised J is then also solved by GMRES, in a few iterations, and in double
/// precision if that fails).
///
/// A GMRES solution is an inexact Newton step with forcing term `accept` (Dembo, Eisenstat &
/// Steihaug 1982): ‖J x − b‖ ≤ accept ‖b‖ keeps the convergence quadratic until the residual
/// has dropped by that factor in one iteration.
class ReusedLuSolver {
public:
  /// `tolerance`: GMRES' own (preconditioned) relative residual; `accept`: the largest true
  /// relative residual ‖J x − b‖ / ‖b‖ taken from GMRES (fresh factors give the LU's own);
  /// `max_iterations`: GMRES iterations (no restart) before a refactorisation.
  explicit ReusedLuSolver(double tolerance = 1e-12, double accept = 1e-11, int max_iterations = 100)
      : tolerance_(tolerance), accept_(accept), max_iterations_(max_iterations) {}

  /// x with J x = b. Throws nothing: a singular J gives non-finite entries (check them).
  Eigen::VectorXd solve(const Eigen::MatrixXd& J, const Eigen::VectorXd& b) {
    return solve(J, b, accept_);
  }
  /// Same, taking a GMRES solution whose true relative residual is at most `accept` (at
  /// least the constructor's: the forcing term of an inexact Newton step) once GMRES has
  /// needed more than cheap_iterations; a cheaper solve still meets the tight acceptance,
  /// unless iterative refinement stalls above it (a pass gaining less than 10x: J's
  /// conditioning floor, which no factors would beat), when `accept` is enough again.
  Eigen::VectorXd solve(const Eigen::MatrixXd& J, const Eigen::VectorXd& b, double accept);
  /// The same for J in operator form: GMRES applies −S x + P x (S streamed once per product
  /// instead of the whole dense J), and J is formed densely only when it is factorised. The
  /// same iterates as the dense solve of the same J, up to round-off.
  Eigen::VectorXd solve(const CondensedNewtonMatrix& J, const Eigen::VectorXd& b, double accept);
  /// GMRES iterations within which a solve meets the tight acceptance whatever `accept`.
  static constexpr int cheap_iterations = 10;
  /// The factors are renewed once the solves on them have taken more than this times n GMRES
  /// iterations (n the matrix size). A factorisation costs O(n³), an iteration O(n²) (the
  /// substitutions and one product), so the budget grows with n. On the pile study at n =
  /// 2400 and 4700 (k = 8, 14), 0.25 to 0.5 took 13 to 20 % off the run (fewer iterations on
  /// fresher factors); 1 and more approach never renewing them (docs/performance_solver_engine.md).
  /// Only from renew_from_rows on: below, a factorisation costs milliseconds and renewing
  /// saves nothing, while it moves round-off and with it Newton's path on the small shipped
  /// inputs (the Coulomb pile, n ≈ 300: 85 linear solves became 108).
  static constexpr double refactor_after = 0.5;
  static constexpr Eigen::Index renew_from_rows = 1000;
  /// Drop the factors and free their memory (the matrices to come are unrelated to the last
  /// one).
  void reset();
  /// Keep the factors of later factorisations in single precision (float).
  void set_single_precision_factors(bool single) { single_ = single; }

  int factorizations() const { return factorizations_; } ///< since construction
  int iterations() const { return iterations_; }         ///< GMRES iterations, in total
  int last_iterations() const { return last_iterations_; }

private:
  template <class Matrix>
  Eigen::VectorXd solve_any(const Matrix& J, const Eigen::VectorXd& b, double accept);
  template <class Matrix> void factorize(const Matrix& J, bool single);
  /// GMRES on the current factors, with up to three passes of iterative refinement; false if
  /// the acceptance is not met (the factors are too far off).
  template <class Matrix>
  bool refine(const Matrix& J, const Eigen::VectorXd& b, double accept, Eigen::VectorXd& x);

  double tolerance_, accept_;
  int max_iterations_;
  int iterations_on_factors_ = 0; ///< GMRES iterations of the solves on the current factors
  bool single_ = false;
  // The factors overwrite the matrix they come from (in-place LU): one n × n array, not two.
  // One of the two precisions is in use.
  Eigen::MatrixXd factors_;
  Eigen::MatrixXf factors_single_;
  std::unique_ptr<Eigen::PartialPivLU<Eigen::Ref<Eigen::MatrixXd>>> lu_;
  std::unique_ptr<Eigen::PartialPivLU<Eigen::Ref<Eigen::MatrixXf>>> lu_single_;
  // With several ranks and J in operator form: GMRES' preconditioner substitutes on shared
  // tiles of the factors (each rank reads 1/ranks of them).
  std::unique_ptr<SplitTriangularSolve<double>> split_;
  std::unique_ptr<SplitTriangularSolve<float>> split_single_;
  Eigen::Index factor_rows_ = 0;
  bool factorized_ = false;
  int factorizations_ = 0, iterations_ = 0, last_iterations_ = 0;
};

} // namespace bipot
