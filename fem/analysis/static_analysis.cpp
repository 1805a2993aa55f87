#include "fem/analysis/static_analysis.hpp"

#include "fem/analysis/initial_stress.hpp"
#include "fem/analysis/result_writer.hpp"
#include "fem/assembly/constraints.hpp"
#include "fem/assembly/load_assembler.hpp"
#include "fem/assembly/solid_assembler.hpp"
#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/dof_distribution.hpp"
#include "fem/linalg/linear_solver.hpp"
#include "fem/linalg/sparse_matrix.hpp"
#include "fem/linalg/sparsity_pattern.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace bipot {

namespace {

// A cell belongs to the rank owning its lowest node: deterministic, no communication, and
// with node-block row ownership most of its rows are local.
std::vector<bool> owned_cell_flags(const Mesh& mesh, const DofDistribution& dist) {
  std::vector<bool> owned(mesh.num_cells());
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Index* nodes = mesh.cell(c);
    const Index lowest = *std::min_element(nodes, nodes + mesh.cell_num_nodes(c));
    owned[c] = dist.owner_of_node(lowest) == dist.rank();
  }
  return owned;
}

std::vector<Index> indices_of(const std::vector<bool>& flags) {
  std::vector<Index> out;
  for (std::size_t i = 0; i < flags.size(); ++i)
    if (flags[i]) out.push_back(static_cast<Index>(i));
  return out;
}

bool all_linear(const Model& model) {
  return std::all_of(model.materials.begin(), model.materials.end(),
                     [](const auto& m) { return m->is_linear(); });
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

struct StaticAnalysis::Impl {
  const Model& model;
  AnalysisOptions options;
  ResultWriter* writer;
  int dim;
  DofMap dofs;
  DofDistribution dist;
  std::vector<bool> cell_owned;
  SolidAssembler solid;
  LoadAssembler loads;
  std::vector<std::unique_ptr<contact::InterfaceAssembler>> interfaces;
  bool has_contact = false; ///< some interface is not tied: the tangent changes
  std::unique_ptr<SparseMatrix> K;
  DistributedVector R, du, F_prev, F_cur, F_step, reaction;
  LinearSolver solver;
  std::vector<double> u;
  std::vector<double> reaction_all;
  bool linear;
  bool matrix_ready = false;                     ///< K and the solver hold the current tangent
  const StaticAnalysis* this_analysis = nullptr; ///< handed to the writer
  RunSummary summary;

  // Boundary-condition targets of the current stage and the values they start from.
  std::map<Index, double> target, start;
  // Interface gap shifts (per interface) at the start and the end of the current stage.
  std::vector<double> gap_start, gap_target;

  Impl(const Model& m, AnalysisOptions o, ResultWriter* w)
      : model(m), options(o), writer(w), dim(spatial_dim(m.kinematics)),
        dofs(m.mesh.num_nodes(), dim), dist(m.mesh.num_nodes(), dim),
        cell_owned(owned_cell_flags(m.mesh, dist)),
        solid(m.mesh, m.kinematics, dofs, m.material_of_region, indices_of(cell_owned)),
        loads(m.mesh, m.kinematics, dofs, cell_owned), R(dist), du(dist), F_prev(dist), F_cur(dist),
        F_step(dist), reaction(dist),
        solver(LinearSolverOptions::from_parameters(m.spec.linear_solver)), u(dofs.num_dofs(), 0.0),
        linear(all_linear(m)) {
    for (std::size_t k = 0; k < m.interfaces.size(); ++k) {
      interfaces.push_back(std::make_unique<contact::InterfaceAssembler>(
          m.interfaces[k], *m.interface_laws[k], dofs, dist));
      has_contact = has_contact || !interfaces.back()->tied();
    }
    SparsityPattern pattern;
    solid.add_to_pattern(pattern);
    for (const auto& ia : interfaces)
      ia->add_to_pattern(pattern);
    K = std::make_unique<SparseMatrix>(dist, pattern);
    std::vector<double> coords;
    for (Index n = dist.first_owned_node(); n < dist.first_owned_node() + dist.num_owned_nodes();
         ++n)
      coords.insert(coords.end(), m.mesh.nodes[n].begin(), m.mesh.nodes[n].end());
    // Axisymmetry too gets the three plane-strain rigid modes: u_r = const costs only
    // ε_θθ = u/r, small away from the axis, so AMG must see it, and the in-plane rotation
    // helps as well. CG + MueLu iterations on a 200x50-cell cylinder wall (r in [1, 2]),
    // axial mode only / both translations / three modes: quad8 341 / 42 / 30 (1 rank),
    // 57 / 49 with 2 ranks; quad4 129 / 18 / 13, 31 / 27 with 2 ranks.
    solver.set_near_null_space(dim, false, coords);
    if (!m.spec.initial_stress.empty()) solid.set_initial_stress(initial_stress_function(m));
    F_prev.set_zero();
    if (has_contact) choose_augmentation();
  }

  // ρ per pair from the bulk stiffness diagonal (one bulk assembly, before any constraint).
  void choose_augmentation() {
    K->set_zero();
    R.set_zero();
    solid.assemble(u, Constraints{}, K.get(), R);
    K->finish_assembly();
    R.finish_assembly();
    const std::vector<double> diagonal = K->diagonal().gather_all();
    for (const auto& ia : interfaces)
      ia->set_augmentation(model.contact_solver, diagonal);
  }

  std::vector<Index> set_nodes(const std::string& name) const {
    auto it = model.mesh.node_sets.find(name);
    if (it != model.mesh.node_sets.end()) return it->second;
    return model.mesh.facet_set_nodes(name);
  }

  void assemble_loads(const StageSpec& stage, DistributedVector& F) const {
    F.set_zero();
    for (const auto& ld : stage.loads) {
      switch (ld.type) {
      case LoadSpec::Type::Pressure:
        loads.add_pressure(ld.set, ld.pressure, F);
        break;
      case LoadSpec::Type::Traction:
        loads.add_traction(ld.set, ld.traction, F);
        break;
      case LoadSpec::Type::Gravity:
        loads.add_gravity(model.material_of_region, F);
        break;
      }
    }
    F.finish_assembly();
  }

  struct IncrementLog {
    int iterations = 0, linear_iterations = 0, uzawa_updates = 0, staggered = 0;
    std::vector<double> history; ///< relative force residual per iteration
    double contact = 0;          ///< last relative multiplier change
    std::string failure;
  };

  bool solve_increment(double lambda, double dtau, IncrementLog& log);
  void tied_interface_forces(double gravity_factor);
  // Share of gravity in the loads at the end of the previous stage and of the current one
  // (0 or 1), ramped like the loads.
  double gravity_before = 0.0, gravity_now = 0.0;
  bool solve_increment_staggered(double lambda, double dtau, IncrementLog& log);
  double residual_norm(const std::vector<double>& trial, double dtau,
                       const Constraints& constraints);
  RunSummary run(const std::function<void(const StepReport&)>& on_step);
};

// ‖R‖ at a trial displacement for the current multipliers (line search merit). Uses R as
// scratch; no matrix.
double StaticAnalysis::Impl::residual_norm(const std::vector<double>& trial, double dtau,
                                           const Constraints& constraints) {
  R.set_zero();
  solid.assemble(trial, constraints, nullptr, R);
  for (const auto& ia : interfaces) {
    ia->evaluate(trial, dtau);
    ia->add_to_system(constraints, nullptr, R);
  }
  R.finish_assembly();
  const Index first = dist.first_owned_dof(), n_owned = dist.num_owned_dofs();
  double* r = R.owned_values();
  const double* f = F_step.owned_values();
  for (Index i = 0; i < n_owned; ++i)
    if (!constraints.is_constrained(first + i)) r[i] += f[i];
  return R.norm2();
}

// Newton (and, for bipotential_uzawa, Uzawa) iterations of one increment ending at stage
// load factor `lambda`. Leaves `u` at the last iterate; the caller restores it on failure.
bool StaticAnalysis::Impl::solve_increment(double lambda, double dtau, IncrementLog& log) {
  const Index first = dist.first_owned_dof(), n_owned = dist.num_owned_dofs();
  const contact::ContactSolverOptions& copt = model.contact_solver;
  const int max_iterations = has_contact ? copt.max_iterations : options.max_iterations;
  const double tolerance = has_contact ? copt.tolerance : options.residual_tolerance;
  F_step.copy(F_prev);
  F_step.scale(1.0 - lambda);
  F_step.axpy(lambda, F_cur);
  for (std::size_t k = 0; k < interfaces.size(); ++k) {
    interfaces[k]->set_gap_shift(gap_start[k] + lambda * (gap_target[k] - gap_start[k]));
    interfaces[k]->begin_increment();
  }

  Constraints constraints;
  double reference = 0.0, baseline = -1.0;
  bool first_pass = true;
  int inner = 0;
  for (;; ++log.iterations, ++inner) {
    constraints.clear();
    for (const auto& [d, v] : target)
      constraints.set(d, first_pass ? start[d] + lambda * (v - start[d]) - u[d] : 0.0);
    auto t0 = std::chrono::steady_clock::now();
    bool tangent_changed = false;
    for (const auto& ia : interfaces) {
      ia->evaluate(u, dtau);
      tangent_changed = tangent_changed || ia->tangent_changed();
    }
    // Prescribed increments are eliminated with the matrix's own diagonal: rebuild then.
    const bool need_matrix = !matrix_ready || !linear || tangent_changed ||
                             (has_contact && first_pass && !target.empty());
    R.set_zero();
    if (need_matrix) K->set_zero();
    solid.assemble(u, constraints, need_matrix ? K.get() : nullptr, R);
    for (const auto& ia : interfaces)
      ia->add_to_system(constraints, need_matrix ? K.get() : nullptr, R);
    R.finish_assembly();
    if (need_matrix) K->finish_assembly();
    double* r = R.owned_values();
    const double* f = F_step.owned_values();
    for (Index i = 0; i < n_owned; ++i)
      if (!constraints.is_constrained(first + i)) r[i] += f[i];
    const double norm = R.norm2();
    double change = 0, force_scale = 0;
    for (const auto& ia : interfaces) {
      change = std::max(change, ia->multiplier_change());
      force_scale = std::max(force_scale, ia->force_scale());
    }
    summary.assembly_seconds += seconds_since(t0);
    if (log.iterations == 0) {
      reference = std::max({norm, F_step.norm2(), force_scale});
      if (reference == 0.0 && change == 0.0) return true; // nothing acts on the body
    }
    reference = std::max(reference, force_scale);
    log.history.push_back(norm / reference);
    log.contact = change / reference;

    const bool force_ok = !first_pass && norm <= tolerance * reference;
    const bool contact_ok = change <= tolerance * reference;
    if (force_ok && contact_ok) return true;
    if (baseline < 0) baseline = norm;
    // When to move the multipliers (the corrector r̂ ← Proj(τ)): bipotential_uzawa once
    // equilibrium holds for the current ones; semismooth_newton as soon as the residual of
    // the current inner problem has dropped tenfold (inexact augmented Lagrangian), so
    // equilibrium and the contact law converge together.
    const bool inner_done = force_ok || (!copt.uzawa() && !first_pass && norm <= 0.1 * baseline);
    if (has_contact && inner_done && !contact_ok) {
      if (log.uzawa_updates >= copt.max_outer_iterations) {
        log.failure = "the Uzawa multipliers did not settle in " +
                      std::to_string(log.uzawa_updates) + " updates";
        return false;
      }
      for (const auto& ia : interfaces)
        ia->update_multipliers();
      ++log.uzawa_updates;
      // K was rebuilt but not factorised: the solver still holds the previous matrix, so
      // it must be set up again even if the next tangent equals the one last factorised.
      if (need_matrix) matrix_ready = false;
      inner = -1;
      baseline = -1; // the next residual, for the new multipliers, is the new baseline
      continue;
    }
    if (inner >= max_iterations) {
      log.failure = "no convergence in " + std::to_string(inner) + " iterations";
      return false;
    }
    if (!std::isfinite(norm)) {
      log.failure = "the residual is not finite";
      return false;
    }
    if (need_matrix) {
      t0 = std::chrono::steady_clock::now();
      solver.setup(*K);
      summary.setup_seconds += seconds_since(t0);
      matrix_ready = true;
      for (const auto& ia : interfaces)
        ia->mark_tangent_assembled();
      ++summary.matrix_setups;
    }
    du.set_zero();
    t0 = std::chrono::steady_clock::now();
    LinearSolveStats stats;
    try {
      stats = solver.solve(R, du);
    } catch (const SolverError& e) {
      log.failure = e.what();
      return false;
    }
    summary.solve_seconds += seconds_since(t0);
    log.linear_iterations += stats.iterations;
    summary.linear_iterations += stats.iterations;
    ++summary.linear_solves;
    const std::vector<double> du_all = du.gather_all();
    double step = 1.0;
    if (has_contact && copt.line_search && !first_pass) {
      // Backtracking on ‖R‖ at fixed multipliers: semi-smooth Newton steps can flip pairs
      // between stick and slip (or open and closed) back and forth; damping breaks the cycle.
      t0 = std::chrono::steady_clock::now();
      // The merit is the free-DOF residual: constrained DOFs keep their (already applied)
      // prescribed values, so their rows are eliminated as in the iteration itself.
      Constraints fixed;
      for (const auto& kv : target)
        fixed.set(kv.first, 0.0);
      std::vector<double> trial(u.size());
      double best = norm, best_step = 1.0;
      bool accepted = false;
      for (int k = 0; k < 8 && !accepted; ++k) {
        for (std::size_t i = 0; i < u.size(); ++i)
          trial[i] = u[i] + step * du_all[i];
        const double merit = residual_norm(trial, dtau, fixed);
        accepted = merit < (1.0 - 1e-4 * step) * norm;
        if (!accepted) {
          if (merit < best) best = merit, best_step = step;
          step *= 0.5;
        }
      }
      // No sufficient decrease: take the best step tried, or the full one if none helped
      // (at a kink the Newton direction need not be a descent direction).
      if (!accepted) step = best < norm ? best_step : 1.0;
      summary.assembly_seconds += seconds_since(t0);
    }
    for (std::size_t i = 0; i < u.size(); ++i)
      u[i] += step * du_all[i];
    first_pass = false;
  }
}

// Tractions of tied (perfect bonding) interfaces, for output: at a shared node the force
// body 1 exerts on body 2 is what body 1's cells do not balance themselves, i.e. minus their
// internal force plus their body force. Needs the interface's body-1 region (`between`);
// surface loads on body-1 facets at interface nodes are not separated out.
void StaticAnalysis::Impl::tied_interface_forces(double gravity_factor) {
  for (std::size_t k = 0; k < interfaces.size(); ++k) {
    const auto& spec = model.spec.interfaces[k];
    if (!interfaces[k]->tied() || spec.between.size() != 2) continue;
    const int region = model.mesh.regions.at(spec.between[0]);
    DistributedVector& f = du; // scratch: du is not needed between increments
    f.set_zero();
    solid.internal_force(u, f, region);
    f.finish_assembly();
    std::vector<const Material*> body1(model.material_of_region.size(), nullptr);
    body1[region] = model.material_of_region[region];
    DistributedVector& g = R; // scratch as well
    g.set_zero();
    loads.add_gravity(body1, g);
    g.finish_assembly();
    f.axpy(-gravity_factor, g);
    f.scale(-1.0);
    // At a supported node body 1's force also carries the support's reaction: the interface's
    // share is unknown there, so it is reported as NaN (a gap in plots).
    std::vector<double> force = f.gather_all();
    for (const auto& kv : target)
      force[kv.first] = std::numeric_limits<double>::quiet_NaN();
    interfaces[k]->set_tied_forces(force);
  }
}

// Fallback for an increment the monolithic iteration cannot solve even at the smallest step:
// a debonding snap-back, where β = min(β_old, w/E) has no solution continuous with the last
// state (Newton cycles between states). Alternate a solve with β held fixed (a well-posed
// contact problem) and the update of β from the displacement. β only decreases along this
// sequence, which therefore converges, to the equilibrium after the jump; the monolithic
// iteration then confirms it with the true law. Leaves `u` at the last iterate.
bool StaticAnalysis::Impl::solve_increment_staggered(double lambda, double dtau,
                                                     IncrementLog& log) {
  constexpr int max_updates = 200;
  constexpr double beta_tolerance = 1e-6; // the monolithic check with the true law decides
  std::vector<std::vector<double>> beta(interfaces.size());
  for (std::size_t k = 0; k < interfaces.size(); ++k)
    beta[k] = interfaces[k]->committed_adhesion();
  auto merge = [&log](const IncrementLog& sub) {
    log.iterations += sub.iterations;
    log.linear_iterations += sub.linear_iterations;
    log.uzawa_updates += sub.uzawa_updates;
    log.history = sub.history;
    log.contact = sub.contact;
    log.failure = sub.failure;
  };
  auto unfreeze = [&] {
    for (const auto& ia : interfaces)
      ia->unfreeze_adhesion();
  };
  for (int it = 0; it < max_updates; ++it) {
    for (std::size_t k = 0; k < interfaces.size(); ++k)
      interfaces[k]->freeze_adhesion(beta[k]);
    IncrementLog sub;
    const bool ok = solve_increment(lambda, dtau, sub);
    merge(sub);
    ++log.staggered;
    if (!ok) {
      unfreeze();
      log.failure = "staggered fallback, with beta held: " + log.failure;
      return false;
    }
    double change = 0;
    for (std::size_t k = 0; k < interfaces.size(); ++k) {
      std::vector<double> next = interfaces[k]->adhesion_at(u, dtau);
      for (std::size_t i = 0; i < next.size(); ++i)
        change = std::max(change, std::abs(next[i] - beta[k][i]));
      beta[k] = std::move(next);
    }
    if (change <= beta_tolerance) break;
  }
  unfreeze();
  IncrementLog final_check;
  const bool ok = solve_increment(lambda, dtau, final_check);
  merge(final_check);
  if (!ok) log.failure = "staggered fallback, final check with the true law: " + log.failure;
  return ok;
}

RunSummary StaticAnalysis::Impl::run(const std::function<void(const StepReport&)>& on_step) {
  const auto run_start = std::chrono::steady_clock::now();
  summary = RunSummary{};
  summary.num_dofs = dofs.num_dofs();
  const int max_cutbacks = model.contact_solver.max_cutbacks;
  double time = 0.0;
  // Interface resultants (per interface and component) of the last step and the largest
  // magnitudes seen, for the snap-back flag.
  std::vector<std::array<double, 3>> last_resultant(interfaces.size(), {0, 0, 0});
  std::vector<std::array<double, 3>> largest_resultant(interfaces.size(), {0, 0, 0});
  double largest_any = 0.0;

  for (std::size_t s = 0; s < model.spec.stages.size(); ++s) {
    const StageSpec& stage = model.spec.stages[s];
    target.clear();
    for (const auto& bc : stage.boundary_conditions)
      for (Index node : set_nodes(bc.set))
        target[dofs.dof(node, bc.component)] = bc.value;
    start.clear();
    for (const auto& [d, v] : target)
      start[d] = u[d];
    assemble_loads(stage, F_cur);
    gravity_now = std::any_of(stage.loads.begin(), stage.loads.end(),
                              [](const LoadSpec& l) { return l.type == LoadSpec::Type::Gravity; });
    matrix_ready = false; // the constrained set may have changed
    // A gap shift not named by the stage keeps its value (it is a state, not a load).
    gap_start.resize(interfaces.size());
    gap_target.resize(interfaces.size());
    for (std::size_t k = 0; k < interfaces.size(); ++k) {
      gap_start[k] = gap_target[k] = interfaces[k]->gap_shift();
      for (const auto& gap : stage.interface_gaps)
        if (gap.interface == model.interfaces[k].name) gap_target[k] = gap.value;
    }

    const double planned = 1.0 / stage.increments;
    double done = 0.0;
    int level = 0, step = 0;
    while (done < 1.0 - 1e-12) {
      const auto step_start = std::chrono::steady_clock::now();
      const double size = planned / std::pow(2.0, level);
      const double lambda = std::min(1.0, done + size);
      const std::vector<double> u_begin = u;
      IncrementLog log;
      const double dtau = (lambda - done) * stage.duration;
      bool converged = solve_increment(lambda, dtau, log);
      if (!converged) {
        u = u_begin;
        matrix_ready = false;
        if (level < max_cutbacks) {
          ++level;
          continue;
        }
        if (has_contact) {
          IncrementLog staggered;
          converged = solve_increment_staggered(lambda, dtau, staggered);
          if (converged) {
            log = staggered;
            ++summary.staggered_increments;
          } else {
            u = u_begin;
            matrix_ready = false;
            log.failure += "; then " + staggered.failure + " after " +
                           std::to_string(staggered.staggered) + " beta updates";
          }
        }
      }
      if (!converged) {
        std::ostringstream msg;
        msg << "stage '" << stage.name << "' (" << s + 1 << "), step " << step + 1 << " of "
            << stage.increments << " (load factor " << done << " -> " << lambda << " after "
            << level << " cut-backs): " << log.failure << "; relative residual history:";
        for (double h : log.history)
          msg << " " << h;
        msg << "; multiplier change " << log.contact
            << ". Converged increments are in the output directory.";
        throw SolverError(msg.str());
      }
      solid.commit();
      for (const auto& ia : interfaces)
        ia->commit();
      auto t0 = std::chrono::steady_clock::now();
      // Reaction = f_int − f_interfaces − f_ext: a supported node on an interface (the top
      // of a pile shaft) also carries the interface force of its pair.
      reaction.set_zero();
      solid.internal_force(u, reaction);
      reaction.finish_assembly();
      reaction.axpy(-1.0, F_step);
      if (has_contact) {
        R.set_zero();
        for (const auto& ia : interfaces)
          ia->add_to_system(Constraints{}, nullptr, R);
        R.finish_assembly();
        reaction.axpy(-1.0, R);
      }
      reaction_all = reaction.gather_all();
      tied_interface_forces((1.0 - lambda) * gravity_before + lambda * gravity_now);
      summary.assembly_seconds += seconds_since(t0);

      StepReport rep;
      rep.stage = stage.name;
      rep.stage_index = static_cast<int>(s);
      rep.step = ++step;
      rep.steps = stage.increments;
      rep.global_step = ++summary.steps;
      rep.time = time + lambda * stage.duration;
      rep.load_factor = lambda;
      rep.iterations = log.iterations;
      rep.linear_iterations = log.linear_iterations;
      rep.uzawa_updates = log.uzawa_updates;
      rep.residual = log.history.empty() ? 0.0 : log.history.back();
      rep.cutbacks = level;
      rep.staggered = log.staggered;
      rep.unstable = level > 0 || log.staggered > 0;
      // Snap-back: a resultant component lost over 20% of the largest value it has had, and
      // the loss is over 5% of the largest interface force of the model (so that a small
      // interface unloading smoothly, like a pile toe, is not flagged).
      for (std::size_t k = 0; k < interfaces.size(); ++k) {
        const auto f = interfaces[k]->resultant();
        for (int c = 0; c < 3; ++c) {
          const double drop = std::abs(last_resultant[k][c]) - std::abs(f[c]);
          if (drop > 0.2 * largest_resultant[k][c] && drop > 0.05 * largest_any)
            rep.unstable = true;
          largest_resultant[k][c] = std::max(largest_resultant[k][c], std::abs(f[c]));
          largest_any = std::max(largest_any, largest_resultant[k][c]);
        }
        last_resultant[k] = f;
      }
      rep.seconds = seconds_since(step_start);
      t0 = std::chrono::steady_clock::now();
      if (writer) writer->write_step(rep, *this_analysis);
      summary.output_seconds += seconds_since(t0);
      if (on_step) on_step(rep);
      done = lambda;
      if (level > 0) --level; // grow back towards the planned increment
    }
    F_prev.copy(F_cur);
    gravity_before = gravity_now;
    time += stage.duration;
    if (stage.reset_displacements) {
      solid.absorb_stress_into_initial(u);
      for (const auto& ia : interfaces)
        ia->absorb_displacements();
      std::fill(u.begin(), u.end(), 0.0);
    }
  }
  summary.seconds = seconds_since(run_start);
  return summary;
}

const std::vector<std::unique_ptr<contact::InterfaceAssembler>>&
StaticAnalysis::interfaces() const {
  return impl_->interfaces;
}

StaticAnalysis::StaticAnalysis(const Model& model, AnalysisOptions options, ResultWriter* writer)
    : impl_(std::make_unique<Impl>(model, options, writer)) {
  impl_->this_analysis = this;
}

StaticAnalysis::~StaticAnalysis() = default;

RunSummary StaticAnalysis::run(const std::function<void(const StepReport&)>& on_step) {
  return impl_->run(on_step);
}

const std::vector<double>& StaticAnalysis::displacement() const {
  return impl_->u;
}
const DofMap& StaticAnalysis::dofs() const {
  return impl_->dofs;
}

std::vector<double> StaticAnalysis::reaction(const std::string& set) const {
  std::vector<double> sum(impl_->dim, 0.0);
  if (impl_->reaction_all.empty()) return sum;
  for (Index node : impl_->set_nodes(set))
    for (int i = 0; i < impl_->dim; ++i)
      sum[i] += impl_->reaction_all[impl_->dofs.dof(node, i)];
  return sum;
}

void StaticAnalysis::cell_results(std::vector<Index>& cells, std::vector<double>& strain,
                                  std::vector<double>& stress) const {
  cells = impl_->solid.owned_cells();
  impl_->solid.cell_averages(strain, stress);
}

} // namespace bipot
