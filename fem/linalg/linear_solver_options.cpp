// The schema of LinearSolverOptions: kept apart from linear_solver.cpp so that
// editing docs or defaults does not recompile the Belos/MueLu translation unit.
#include "fem/linalg/linear_solver.hpp"

#include "fem/core/error.hpp"

#include <cstdlib>
#include <filesystem>

namespace bipot {

ParamSchemaOf<LinearSolverOptions> LinearSolver::schema() {
  using O = LinearSolverOptions;
  ParamSchemaOf<O> s("linear_solver",
                     "Solver for the linear systems of each Newton/Uzawa iteration");
  s.string("method", &O::method,
           "Krylov method (cg for symmetric positive definite systems, gmres "
           "otherwise) or a direct sparse LU factorisation (see `factorization`)")
      .one_of({"cg", "gmres", "direct"})
      .defaulted();
  s.string("preconditioner", &O::preconditioner,
           "muelu: smoothed-aggregation algebraic multigrid; lu: the sparse LU of an "
           "earlier matrix, refactorised as `lu_refresh` says (for Newton iterations that "
           "change only a few rows, as contact ones do); ilu: incomplete LU(0) per rank; "
           "jacobi: diagonal scaling; none")
      .one_of({"muelu", "lu", "ilu", "jacobi", "none"})
      .defaulted();
  s.real("tolerance", &O::tolerance, "",
         "Relative residual ||b - A x|| / ||b|| at which iterations stop")
      .greater_than(0.0)
      .less_than(1.0)
      .defaulted();
  s.integer("max_iterations", &O::max_iterations,
            "Maximum number of Krylov iterations (restarts included)")
      .at_least(1)
      .defaulted();
  s.integer("restart", &O::restart, "GMRES: Krylov subspace size before a restart")
      .at_least(1)
      .defaulted();
  s.integer("amg_coarse_size", &O::amg_coarse_size,
            "MueLu: coarsening stops below this many rows; the coarsest "
            "level is solved directly")
      .at_least(1)
      .defaulted();
  s.string("factorization", &O::factorization,
           "Sparse factorisation package for method `direct` and preconditioner `lu`, on the "
           "matrix gathered on rank 0. mumps: multifrontal (MUMPS), LDL^T of a symmetric "
           "matrix (without pivoting while positive definite), LU of any other; 3 times "
           "faster than klu2 at 78k DOFs and 10 times at 306k (docs/performance.md); "
           "klu2: Amesos2's left-looking LU")
      .one_of({"mumps", "klu2"})
      .defaulted();
  s.integer("lu_refresh", &O::lu_refresh,
            "lu: GMRES iterations, in all since the last factorisation, after "
            "which the current matrix is factorised; 0 = automatic: once the "
            "GMRES time on the old factors equals the time of one factorisation")
      .at_least(0)
      .defaulted();
  s.boolean("verbose", &O::verbose, "Print the Krylov convergence history").defaulted();
  s.boolean("out_of_core", &O::out_of_core,
            "MUMPS writes its factors (generalized_newton's condensed bulk, `direct`, "
            "`lu`) to files in the temporary directory (TMPDIR) instead of keeping them in "
            "memory, for models whose factors do not fit (the pile at 307k DOFs: peak memory "
            "794 -> 533 MB, docs/performance_solver_engine.md); the files are deleted with "
            "the solver")
      .defaulted();
  s.rule("preconditioner",
         "preconditioner `lu` needs method `gmres`: old LU factors are a nonsymmetric "
         "preconditioner, on which CG breaks down (and `direct` takes no preconditioner)",
         [](const O& o) -> std::optional<std::string> {
           if (o.preconditioner != "lu" || o.method == "gmres") return {};
           return "preconditioner 'lu' needs method 'gmres', got method '" + o.method +
                  "': old LU factors are a nonsymmetric preconditioner";
         });
  return s;
}

std::string factor_directory(const LinearSolverOptions& options) {
  if (!options.out_of_core) return "";
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  if (ec)
    throw Error("linear_solver.out_of_core: no temporary directory for the factor files (" +
                ec.message() + "; TMPDIR is '" +
                (std::getenv("TMPDIR") ? std::string(std::getenv("TMPDIR")) : std::string()) +
                "'): set TMPDIR to a writable directory");
  // MUMPS takes the directory in a fixed 256-character field: a longer path would be cut.
  if (dir.string().size() >= 256)
    throw Error("linear_solver.out_of_core: the temporary directory '" + dir.string() +
                "' is longer than the 255 characters MUMPS takes; set TMPDIR to a shorter path");
  return dir.string();
}

} // namespace bipot
