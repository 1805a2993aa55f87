#pragma once
/// Krylov and direct solvers for SparseMatrix systems (Belos, MueLu, Ifpack2, Amesos2).

#include "fem/core/parameter_binding.hpp"

#include <memory>
#include <string>
#include <vector>

namespace bipot {

class DistributedVector;
class SparseMatrix;

/// How a LinearSolver solves. LinearSolver::schema() declares the keys bound to these members
/// (fill() builds the struct from validated YAML input); the constructor from a plain struct
/// validates it through the same schema.
struct LinearSolverOptions {
  std::string method = "cg";            ///< cg | gmres | direct
  std::string preconditioner = "muelu"; ///< muelu | lu | ilu | jacobi | none (not for direct)
  double tolerance = 1e-10;             ///< relative residual ||b - A x|| / ||b|| to reach
  int max_iterations = 2000;            ///< Krylov iterations in all (restarts included)
  int restart = 200;                    ///< GMRES Krylov subspace size before a restart
  int amg_coarse_size = 1000;           ///< MueLu: stop coarsening below this many rows
  std::string factorization = "mumps";  ///< direct and lu: mumps | klu2 (sparse LU package)
  int lu_refresh = 0;       ///< lu: refactorise after this many GMRES iterations on old factors;
                            ///< 0 = once the time spent on them reaches one factorisation's
  bool verbose = false;     ///< print Krylov convergence history (rank 0)
  bool out_of_core = false; ///< MUMPS factors in files in the temporary directory
};

/// Where MUMPS writes its factors under these options: the system's temporary directory
/// (TMPDIR) if `out_of_core`, else "" (in memory). Throws bipot::Error if there is none (TMPDIR
/// not a directory) or its path is too long for MUMPS.
std::string factor_directory(const LinearSolverOptions& options);

/// Outcome of LinearSolver::solve().
struct LinearSolveStats {
  int iterations = 0;           ///< Krylov iterations (0 for direct)
  double relative_residual = 0; ///< ||b - A x|| / ||b||, recomputed explicitly
  double setup_seconds = 0;     ///< last setup(): preconditioner or factorisation
  double solve_seconds = 0;
  bool converged = false; ///< always true on return: failure throws
};

/// Solves A x = b for a SparseMatrix A with Belos "Pseudo Block CG" / "Pseudo Block GMRES"
/// (right preconditioning for GMRES) or a sparse LU, MUMPS or Amesos2 KLU2 (the matrix
/// gathered on rank 0).
/// Preconditioners: MueLu smoothed aggregation ("number of equations" = DOFs per node,
/// near-null space from set_near_null_space(), symmetric Gauss-Seidel smoothing, W-cycle, KLU2
/// coarse solve on one rank and per-rank deep-fill ILU on several), Ifpack2 ILU(0) (RILUK, per
/// rank), Ifpack2 Jacobi, and "lu": the LU factors of an earlier matrix (refactorised at
/// the next setup() once the GMRES time on them has reached the time of one factorisation, or
/// after `lu_refresh` iterations if given; at once if GMRES reaches that limit within a solve).
/// The direct solver's tolerance check is loosened to max(tolerance, 1e-6): its accuracy is set
/// by conditioning, not iterations.
///
/// Usage: setup(A) after each assembly of A, then solve() any number of times. The solver
/// keeps a reference to A's values, so setup() must follow every refill. Calling setup() again
/// after refilling the same matrix reuses MueLu's aggregates and tentative prolongator, and the
/// LU's symbolic analysis; MueLu is rebuilt from scratch instead if an entry stored as 0.0 at
/// its last build has become nonzero (a contact or friction coupling switching on), which its
/// reused matrix products cannot take.
class LinearSolver {
public:
  /// Throws bipot::InputError listing every invalid option with the allowed values.
  explicit LinearSolver(const LinearSolverOptions& options)
      : LinearSolver(schema().checked(options)) {}
  /// Options already validated (schema().fill of the input's, or schema().checked).
  explicit LinearSolver(Checked<LinearSolverOptions> options);
  ~LinearSolver();
  LinearSolver(LinearSolver&&) noexcept;
  LinearSolver& operator=(LinearSolver&&) noexcept;

  const LinearSolverOptions& options() const { return options_; }

  /// Near-null space for MueLu. `dim` 2 or 3; `owned_node_coords` holds x, y, z of each
  /// owned node in order (3 per node, z ignored in 2D). Plane strain: 2 translations and the
  /// in-plane rotation; 3D: 3 translations and 3 rotations; axisymmetric (x = r, y = z): the
  /// axial translation (the only zero-energy mode) and the radial one, u_r = const, whose
  /// energy comes only from eps_thetatheta = u_r / r: without it multigrid convergence
  /// degrades with mesh refinement. Takes effect at the next setup().
  void set_near_null_space(int dim, bool axisymmetric,
                           const std::vector<double>& owned_node_coords);

  /// Builds the preconditioner or factorisation for A (collective).
  void setup(const SparseMatrix& A);

  /// Solves A x = b with x as initial guess (collective). Throws bipot::SolverError with
  /// the iteration count and relative residual if the tolerance is not reached; x then
  /// holds the last iterate.
  LinearSolveStats solve(const DistributedVector& b, DistributedVector& x);

  /// Keys, types, defaults and allowed values of LinearSolverOptions ("linear_solver").
  static ParamSchemaOf<LinearSolverOptions> schema();

private:
  struct Impl;
  LinearSolverOptions options_;
  std::unique_ptr<Impl> impl_;
};

} // namespace bipot
