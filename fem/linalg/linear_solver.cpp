#include "fem/linalg/linear_solver.hpp"

#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/detail/lu_preconditioner.hpp"
#include "fem/linalg/detail/rooted_direct_solver.hpp"
#include "fem/linalg/detail/tpetra_types.hpp"

#include <BelosLinearProblem.hpp>
#include <BelosPseudoBlockCGSolMgr.hpp>
#include <BelosPseudoBlockGmresSolMgr.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Ifpack2_Factory.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

namespace bipot {

namespace {

using detail::CrsMatrix;
using detail::GO;
using detail::MultiVector;
using detail::Operator;
using Node = detail::Map::node_type;
using MueLuOperator = MueLu::TpetraOperator<double, int, GO, Node>;
using RowMatrix = Tpetra::RowMatrix<double, int, GO, Node>;
using Ifpack2Preconditioner = Ifpack2::Preconditioner<double, int, GO, Node>;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Tpetra 13.2's CPU sparse matrix-matrix products leave out of the product's graph every
// term whose left factor is a stored entry equal to 0.0, and their reuse path (which MueLu's
// "reuse: type" takes for the smoothed prolongator D⁻¹A P_tent and the Galerkin product
// Pᵀ A P) throws "Trying to insert a new entry into a static graph" when such an entry has
// become nonzero since. Our graphs keep every coupling that may ever be active (contact pairs,
// friction, adhesion), so a tangent often stores exact zeros that a later Newton iteration
// fills in: the hierarchy must then be rebuilt. (Later Trilinos versions can keep explicit
// zeros in products; 13.2 cannot.) Only A is checked: a coarse operator or P entry that
// cancels to exactly 0.0 at a build and not later would still throw (not seen so far).

/// Offsets, in A's local value array, of the stored entries that are exactly zero.
std::vector<std::size_t> zero_entries(const CrsMatrix& A) {
  const auto values = A.getLocalMatrixHost().values;
  std::vector<std::size_t> zeros;
  for (std::size_t k = 0; k < values.extent(0); ++k)
    if (values(k) == 0.0) zeros.push_back(k);
  return zeros;
}

/// True on every rank if some entry listed in `zeros` is nonzero on some rank (collective).
bool zeros_filled_in(const CrsMatrix& A, const std::vector<std::size_t>& zeros) {
  const auto values = A.getLocalMatrixHost().values;
  const bool local =
      std::any_of(zeros.begin(), zeros.end(), [&](std::size_t k) { return values(k) != 0.0; });
  return sum_all(static_cast<Index>(local)) > 0;
}

std::string format_residual(double r) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6e", r);
  return buf;
}

} // namespace

struct LinearSolver::Impl {
  // Near-null space as given (applied at the next MueLu build).
  int nns_dim = 0;
  bool nns_axisymmetric = false;
  std::vector<double> nns_coords;
  bool nns_changed = false;

  Teuchos::RCP<CrsMatrix> A;           ///< the matrix of the last setup()
  std::optional<DofDistribution> dist; ///< of the last setup() matrix
  Teuchos::RCP<MueLuOperator> muelu;
  std::vector<std::size_t> muelu_zeros; ///< zero_entries(*A) when muelu was built
  Teuchos::RCP<Ifpack2Preconditioner> ifpack;
  std::unique_ptr<detail::RootedDirectSolver> direct;
  Teuchos::RCP<detail::LuPreconditioner> lu; ///< preconditioner "lu"
  int lu_iterations = 0;                     ///< GMRES iterations on the current lu factors
  double lu_factor_seconds = 0, lu_stale_seconds = 0; ///< last factorisation; GMRES since
  double lu_iteration_seconds = 0; ///< cost of one GMRES iteration on lu factors (last solve)
  bool lu_current = false;         ///< lu factors are of the matrix of the last setup()
  Teuchos::RCP<detail::Vector> b_work, x_work, r_work;
  double setup_seconds = 0;

  Teuchos::RCP<MultiVector> near_null_space(const SparseMatrix::Impl& m) const;

  void factorize_lu() {
    const auto t0 = std::chrono::steady_clock::now();
    lu->factorize(A);
    // Every rank must take the same refresh decisions (they start collective factorisations
    // and bound collective GMRES runs), so the times they rest on are the slowest rank's:
    // local clocks differ under load, and two ranks once disagreed and waited for each other
    // for ever (one in the factorisation's gather, the other in GMRES).
    lu_factor_seconds = max_all(seconds_since(t0));
    lu_stale_seconds = 0;
    lu_iterations = 0;
    lu_current = true;
  }
  /// GMRES iterations a solve on old factors may take before refactorising is cheaper.
  int stale_lu_limit(const LinearSolverOptions& o) const {
    if (o.lu_refresh > 0) return std::max(1, o.lu_refresh - lu_iterations);
    // Every solve on lu factors measured its cost per iteration; the first stale solve comes
    // after at least one fresh one (setup() factorises first), so the estimate exists.
    const double left = std::max(0.0, lu_factor_seconds - lu_stale_seconds);
    // A solve faster than the clock's resolution: no limit from time.
    if (!(lu_iteration_seconds > 0)) return o.max_iterations;
    const double budget = std::min<double>(left / lu_iteration_seconds, o.max_iterations);
    return std::max(1, static_cast<int>(budget));
  }
};

Teuchos::RCP<MultiVector> LinearSolver::Impl::near_null_space(const SparseMatrix::Impl& m) const {
  const int dpn = m.dist.dofs_per_node();
  const Index n_nodes = m.dist.num_owned_nodes();
  if (dpn != nns_dim)
    throw InputError("linear_solver: near-null space for dimension " + std::to_string(nns_dim) +
                     " needs " + std::to_string(nns_dim) + " DOFs per node, the matrix has " +
                     std::to_string(dpn));
  if (static_cast<Index>(nns_coords.size()) != 3 * n_nodes)
    throw InputError("linear_solver: near-null space got " + std::to_string(nns_coords.size()) +
                     " coordinates, expected 3 per owned node (" + std::to_string(3 * n_nodes) +
                     ")");
  // Rotations about the global centroid: keeps them well separated from the translations
  // when the mesh sits far from the origin.
  double centre[3] = {0, 0, 0};
  for (int c = 0; c < 3; ++c) {
    double local = 0;
    for (Index i = 0; i < n_nodes; ++i)
      local += nns_coords[3 * i + c];
    const Index total = std::max<Index>(1, sum_all(n_nodes));
    centre[c] = sum_all(local) / static_cast<double>(total);
  }
  // Axisymmetric: u_z = const is the only zero-energy mode, but u_r = const (energy from
  // eps_thetatheta = u_r / r only) is a low-energy one that the coarse spaces must contain:
  // without it, CG iterations doubled with each mesh refinement in our trials (32, 58, 111
  // on 16x32 .. 64x128 cylinders), with it they stayed at 17-21.
  const int n_modes = nns_axisymmetric ? 2 : (nns_dim == 2 ? 3 : 6);
  auto modes = Teuchos::rcp(new MultiVector(m.row_map, n_modes, true));
  for (int k = 0; k < n_modes; ++k) {
    auto v = modes->getDataNonConst(k);
    for (Index i = 0; i < n_nodes; ++i) {
      const double x = nns_coords[3 * i] - centre[0];
      const double y = nns_coords[3 * i + 1] - centre[1];
      const double z = nns_coords[3 * i + 2] - centre[2];
      double* u = v.getRawPtr() + dpn * i;
      if (nns_axisymmetric || nns_dim == 2) {
        if (k < 2)
          u[k] = 1.0;
        else
          u[0] = -y, u[1] = x;
      } else if (k < 3) {
        u[k] = 1.0;
      } else if (k == 3) {
        u[1] = -z, u[2] = y; // rotation about x
      } else if (k == 4) {
        u[0] = z, u[2] = -x; // about y
      } else {
        u[0] = -y, u[1] = x; // about z
      }
    }
  }
  return modes;
}

LinearSolver::LinearSolver(Checked<LinearSolverOptions> options)
    : options_(*options), impl_(std::make_unique<Impl>()) {}

LinearSolver::~LinearSolver() = default;
LinearSolver::LinearSolver(LinearSolver&&) noexcept = default;
LinearSolver& LinearSolver::operator=(LinearSolver&&) noexcept = default;

void LinearSolver::set_near_null_space(int dim, bool axisymmetric,
                                       const std::vector<double>& owned_node_coords) {
  if (dim != 2 && dim != 3)
    throw InputError("linear_solver: near-null space dimension must be 2 or 3, got " +
                     std::to_string(dim));
  if (axisymmetric && dim != 2)
    throw InputError("linear_solver: axisymmetric near-null space needs dimension 2");
  // Only the algebraic multigrid uses it; a direct solver keeping a copy of the coordinates
  // would only add to the peak (11 MB at 1M DOFs).
  if (options_.method == "direct") return;
  impl_->nns_dim = dim;
  impl_->nns_axisymmetric = axisymmetric;
  impl_->nns_coords = owned_node_coords;
  impl_->nns_changed = true;
}

void LinearSolver::setup(const SparseMatrix& matrix) {
  const auto start = std::chrono::steady_clock::now();
  auto& im = *impl_;
  const SparseMatrix::Impl& m = *matrix.impl_;
  if (m.assembling) throw Error("LinearSolver::setup: matrix assembly not finished");
  // Holding the RCP keeps the old matrix alive, so equal pointers mean the same matrix.
  const bool same_matrix = im.A.get() == m.matrix.get();
  im.A = m.matrix;
  im.dist = m.dist;
  const auto& o = options_;
  try {
    if (o.method == "direct") {
      if (!im.direct)
        im.direct =
            std::make_unique<detail::RootedDirectSolver>(o.factorization, factor_directory(o));
      im.direct->factorize(im.A); // reuses the gathered structure for the same matrix
    } else if (o.preconditioner == "muelu") {
      if (same_matrix && !im.muelu.is_null() && !im.nns_changed &&
          !zeros_filled_in(*im.A, im.muelu_zeros)) {
        MueLu::ReuseTpetraPreconditioner(im.A, *im.muelu);
      } else {
        Teuchos::ParameterList p;
        p.set("verbosity", o.verbose ? "low" : "none");
        p.set("number of equations", m.dist.dofs_per_node());
        p.set("multigrid algorithm", "sa");
        p.set("coarse: max size", o.amg_coarse_size);
        // Symmetric Gauss-Seidel: a symmetric smoother, as CG needs, and twice as effective
        // as Chebyshev on stretched plane-strain meshes in our tests.
        p.set("smoother: type", "RELAXATION");
        p.sublist("smoother: params").set("relaxation: type", "Symmetric Gauss-Seidel");
        // Amesos2 13.2 as packaged gives wrong solutions for a matrix spread over several
        // ranks (see detail/rooted_direct_solver.hpp), which MueLu's KLU2 coarse solver
        // would be in parallel: there, an incomplete LU with deep fill on each rank's block.
        if (m.dist.size() > 1) {
          p.set("coarse: type", "RILUK");
          p.sublist("coarse: params").set("fact: iluk level-of-fill", 10);
        }
        // Keep aggregates and the tentative prolongator across refills: they depend on the
        // graph and the near-null space only (no drop tolerance), so reuse is exact.
        p.set("reuse: type", "tP");
        // R = Pᵀ applied implicitly: one operator fewer per level (memory at 1M DOFs).
        p.set("transpose: use implicit", true);
        // Pᵀ A P in one pass, without storing A P: peak memory at 1M DOFs (axisymmetric
        // elasticity bench) 1134 -> 942 MB, for about twice the set-up time (8.5 s there).
        p.set("rap: triple product", true);
        // W-cycle: CG iterations 9, 10, 11 at 10k, 100k, 1M DOFs against 11, 12, 15 with a
        // V-cycle, for about the same solve time (the coarse levels are 6-9 times smaller).
        p.set("cycle type", "W");
        if (im.nns_dim > 0) p.sublist("user data").set("Nullspace", im.near_null_space(m));
        im.muelu = Teuchos::null; // free the old hierarchy before building the new one
        im.muelu = MueLu::CreateTpetraPreconditioner(Teuchos::RCP<Operator>(im.A), p);
        im.muelu_zeros = zero_entries(*im.A);
        im.nns_changed = false;
      }
    } else if (o.preconditioner == "lu") {
      // Ski-rental rule: keep paying GMRES iterations on old factors until they have cost
      // as much as a new factorisation (at most twice the best choice in hindsight).
      const bool worn = o.lu_refresh > 0 ? im.lu_iterations >= o.lu_refresh
                                         : im.lu_stale_seconds >= im.lu_factor_seconds;
      if (im.lu.is_null() || !same_matrix || worn) {
        if (im.lu.is_null())
          im.lu = Teuchos::rcp(new detail::LuPreconditioner(o.factorization, factor_directory(o)));
        im.factorize_lu();
      } else {
        im.lu_current = false;
      }
    } else if (o.preconditioner == "ilu" || o.preconditioner == "jacobi") {
      if (!same_matrix || im.ifpack.is_null()) {
        Teuchos::ParameterList p;
        if (o.preconditioner == "ilu") {
          p.set("fact: iluk level-of-fill", 0);
          im.ifpack = Ifpack2::Factory::create<RowMatrix>("RILUK", im.A);
        } else {
          p.set("relaxation: type", "Jacobi");
          p.set("relaxation: sweeps", 1);
          im.ifpack = Ifpack2::Factory::create<RowMatrix>("RELAXATION", im.A);
        }
        im.ifpack->setParameters(p);
        im.ifpack->initialize();
      }
      im.ifpack->compute();
    }
  } catch (const std::exception& e) {
    // Half-built state must not be used by solve(): require a successful setup() first.
    im.A = Teuchos::null;
    im.muelu = Teuchos::null;
    im.ifpack = Teuchos::null;
    im.direct.reset();
    im.lu = Teuchos::null;
    if (dynamic_cast<const Error*>(&e)) throw;
    throw SolverError("linear solver setup (" + o.method + " + " + o.preconditioner +
                      ") failed: " + e.what());
  }
  if (im.b_work.is_null() || !same_matrix) {
    im.b_work = Teuchos::rcp(new detail::Vector(m.row_map));
    im.x_work = Teuchos::rcp(new detail::Vector(m.row_map));
    im.r_work = Teuchos::rcp(new detail::Vector(m.row_map));
  }
  im.setup_seconds = seconds_since(start);
}

LinearSolveStats LinearSolver::solve(const DistributedVector& b, DistributedVector& x) {
  const auto start = std::chrono::steady_clock::now();
  auto& im = *impl_;
  if (im.A.is_null()) throw Error("LinearSolver::solve called before setup()");
  const auto& dist = *im.dist;
  if (b.distribution() != dist || x.distribution() != dist)
    throw Error("LinearSolver::solve: vector distribution differs from the matrix's");
  const auto& o = options_;
  LinearSolveStats stats;
  stats.setup_seconds = im.setup_seconds;

  const double b_norm = b.norm2();
  if (b_norm == 0.0) { // the solution is 0; relative residuals would divide by zero
    x.set_zero();
    stats.converged = true;
    stats.solve_seconds = seconds_since(start);
    return stats;
  }
  detail::copy_to_tpetra(b, *im.b_work);
  detail::copy_to_tpetra(x, *im.x_work);
  bool reached = false;
  try {
    if (o.method == "direct") {
      im.direct->solve(b.owned_values(), x.owned_values());
      detail::copy_to_tpetra(x, *im.x_work); // for the residual below
    } else {
      using Problem = Belos::LinearProblem<double, MultiVector, Operator>;
      auto problem = Teuchos::rcp(new Problem(im.A, im.x_work, im.b_work));
      Teuchos::RCP<Operator> prec;
      if (!im.muelu.is_null() && o.preconditioner == "muelu")
        prec = im.muelu;
      else if (o.preconditioner == "lu")
        prec = im.lu;
      else if (!im.ifpack.is_null() && o.preconditioner != "none")
        prec = im.ifpack;
      // CG needs a symmetric preconditioner on either side; GMRES on the right keeps its
      // implicit residual equal to the true one.
      if (!prec.is_null()) {
        if (o.method == "cg")
          problem->setLeftPrec(prec);
        else
          problem->setRightPrec(prec);
      }
      // Old LU factors get at most the iterations left before a refresh: past that, factorising
      // the current matrix is the cheaper way to finish this solve.
      const bool stale_lu = o.preconditioner == "lu" && !im.lu_current;
      const int limit =
          stale_lu ? std::min(o.max_iterations, im.stale_lu_limit(o)) : o.max_iterations;
      // A Krylov run can stop short of the tolerance with iterations to spare when its
      // recursive residual drifts from the true one (GMRES "loss of accuracy"): restarting
      // from the current iterate recomputes the true residual. Two restarts at most.
      auto krylov = [&](int limit) {
        for (int attempt = 0; attempt < 3 && !reached && stats.iterations < limit; ++attempt) {
          problem->setProblem(); // takes the current x as initial guess
          auto params = Teuchos::rcp(new Teuchos::ParameterList);
          params->set("Convergence Tolerance", o.tolerance);
          params->set("Maximum Iterations", limit - stats.iterations);
          params->set("Implicit Residual Scaling", "Norm of RHS");
          params->set("Verbosity", o.verbose ? Belos::Errors + Belos::Warnings +
                                                   Belos::StatusTestDetails + Belos::FinalSummary
                                             : Belos::Errors);
          if (o.verbose) params->set("Output Frequency", 10);
          Belos::ReturnType result;
          if (o.method == "cg") {
            Belos::PseudoBlockCGSolMgr<double, MultiVector, Operator> solver(problem, params);
            result = solver.solve();
            stats.iterations += solver.getNumIters();
          } else {
            const int remaining = limit - stats.iterations;
            params->set("Explicit Residual Scaling", "Norm of RHS");
            params->set("Num Blocks", std::min(o.restart, remaining));
            params->set("Maximum Restarts", remaining / o.restart + 1);
            Belos::PseudoBlockGmresSolMgr<double, MultiVector, Operator> solver(problem, params);
            result = solver.solve();
            stats.iterations += solver.getNumIters();
          }
          reached = result == Belos::Converged;
        }
      };
      krylov(limit);
      if (o.preconditioner == "lu") {
        im.lu_iterations += stats.iterations;
        const double krylov_seconds = max_all(seconds_since(start)); // same on every rank
        im.lu_iteration_seconds = krylov_seconds / std::max(1, stats.iterations);
        if (stale_lu) im.lu_stale_seconds += krylov_seconds;
        if (!reached && stale_lu) { // refactorise now and finish from the current iterate
          im.factorize_lu();
          stats.setup_seconds += im.lu_factor_seconds;
          const int before = stats.iterations;
          krylov(before + o.max_iterations);
          im.lu_iterations += stats.iterations - before;
        }
      }
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw SolverError("linear solver (" + o.method + " + " + o.preconditioner +
                      ") failed: " + e.what());
  }
  detail::copy_from_tpetra(*im.x_work, x);

  // The explicit residual: what the caller gets, whatever the Krylov method tracked.
  im.A->apply(*im.x_work, *im.r_work);
  im.r_work->update(1.0, *im.b_work, -1.0);
  stats.relative_residual = im.r_work->norm2() / b_norm;
  if (o.method == "direct") // accuracy is set by conditioning: the check is a sanity check
    reached = std::isfinite(stats.relative_residual) &&
              stats.relative_residual <= std::max(o.tolerance, 1e-6);
  stats.solve_seconds = seconds_since(start);
  if (!reached)
    throw SolverError("linear solver (" + o.method + " + " + o.preconditioner +
                      ") did not converge: " + std::to_string(stats.iterations) +
                      " iterations (limit " + std::to_string(o.max_iterations) +
                      "), relative residual " + format_residual(stats.relative_residual) +
                      ", tolerance " + format_residual(o.tolerance) + ", " +
                      std::to_string(dist.num_global_dofs()) + " unknowns");
  stats.converged = true;
  return stats;
}

} // namespace bipot
