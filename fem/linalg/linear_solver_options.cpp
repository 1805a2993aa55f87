// LinearSolverOptions validation and schema: kept apart from linear_solver.cpp so that
// editing docs or defaults does not recompile the Belos/MueLu translation unit.
#include "fem/core/error.hpp"
#include "fem/linalg/linear_solver.hpp"

namespace bipot {

namespace {

ParameterSet to_parameters(const LinearSolverOptions& o) {
  ParameterSet p;
  p.set("method", o.method);
  p.set("preconditioner", o.preconditioner);
  p.set("tolerance", o.tolerance);
  p.set("max_iterations", static_cast<long>(o.max_iterations));
  p.set("restart", static_cast<long>(o.restart));
  p.set("amg_coarse_size", static_cast<long>(o.amg_coarse_size));
  p.set("factorization", o.factorization);
  p.set("lu_refresh", static_cast<long>(o.lu_refresh));
  p.set("verbose", o.verbose);
  return p;
}

} // namespace

ParamSchema LinearSolver::schema() {
  const LinearSolverOptions d;
  ParamSchema s("linear_solver", "Solver for the linear systems of each Newton/Uzawa iteration");
  s.string("method", "Krylov method (cg for symmetric positive definite systems, gmres "
                     "otherwise) or a direct sparse LU factorisation (see `factorization`)")
      .one_of({"cg", "gmres", "direct"})
      .with_default(d.method);
  s.string("preconditioner",
           "muelu: smoothed-aggregation algebraic multigrid; lu: the sparse LU of an "
           "earlier matrix, refactorised as `lu_refresh` says (for Newton iterations that "
           "change only a few rows, as contact ones do); ilu: incomplete LU(0) per rank; "
           "jacobi: diagonal scaling; none")
      .one_of({"muelu", "lu", "ilu", "jacobi", "none"})
      .with_default(d.preconditioner);
  s.real("tolerance", "", "Relative residual ||b - A x|| / ||b|| at which iterations stop")
      .greater_than(0.0)
      .less_than(1.0)
      .with_default(d.tolerance);
  s.integer("max_iterations", "Maximum number of Krylov iterations (restarts included)")
      .at_least(1)
      .with_default(static_cast<long>(d.max_iterations));
  s.integer("restart", "GMRES: Krylov subspace size before a restart")
      .at_least(1)
      .with_default(static_cast<long>(d.restart));
  s.integer("amg_coarse_size", "MueLu: coarsening stops below this many rows; the coarsest "
                               "level is solved directly")
      .at_least(1)
      .with_default(static_cast<long>(d.amg_coarse_size));
  s.string("factorization",
           "Sparse LU package for method `direct` and preconditioner `lu`, on the matrix "
           "gathered on rank 0. mumps: multifrontal (MUMPS), analysis and factorisation 3 "
           "times faster than klu2 at 78k DOFs and 10 times at 306k (docs/performance.md); "
           "klu2: Amesos2's left-looking LU")
      .one_of({"mumps", "klu2"})
      .with_default(d.factorization);
  s.integer("lu_refresh", "lu: GMRES iterations, in all since the last factorisation, after "
                          "which the current matrix is factorised; 0 = automatic: once the "
                          "GMRES time on the old factors equals the time of one factorisation")
      .at_least(0)
      .with_default(static_cast<long>(d.lu_refresh));
  s.boolean("verbose", "Print the Krylov convergence history").with_default(d.verbose);
  s.rule({"preconditioner",
          "preconditioner `lu` needs method `gmres`: old LU factors are a nonsymmetric "
          "preconditioner, on which CG breaks down (and `direct` takes no preconditioner)",
          [](const ParameterSet& p) -> std::optional<std::string> {
            if (p.string("preconditioner") != "lu" || p.string("method") == "gmres") return {};
            return "preconditioner 'lu' needs method 'gmres', got method '" + p.string("method") +
                   "': old LU factors are a nonsymmetric preconditioner";
          }});
  return s;
}

LinearSolverOptions LinearSolverOptions::from_parameters(const ParameterSet& params) {
  LinearSolverOptions o;
  if (params.has("method")) o.method = params.string("method");
  if (params.has("preconditioner")) o.preconditioner = params.string("preconditioner");
  if (params.has("tolerance")) o.tolerance = params.real("tolerance");
  if (params.has("max_iterations"))
    o.max_iterations = static_cast<int>(params.integer("max_iterations"));
  if (params.has("restart")) o.restart = static_cast<int>(params.integer("restart"));
  if (params.has("amg_coarse_size"))
    o.amg_coarse_size = static_cast<int>(params.integer("amg_coarse_size"));
  if (params.has("factorization")) o.factorization = params.string("factorization");
  if (params.has("lu_refresh")) o.lu_refresh = static_cast<int>(params.integer("lu_refresh"));
  if (params.has("verbose")) o.verbose = params.boolean("verbose");
  return o;
}

namespace detail {
// Declared in linear_solver.cpp: throws InputError with every invalid option, one per line.
void validate_linear_solver_options(const LinearSolverOptions& options) {
  ParameterSet given = to_parameters(options);
  validate_or_throw(LinearSolver::schema(), given); // the schema's rules included
}
} // namespace detail

} // namespace bipot
