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
#include <chrono>
#include <cmath>
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
  std::unique_ptr<SparseMatrix> K;
  DistributedVector R, du, F_prev, F_cur, F_step, reaction;
  LinearSolver solver;
  std::vector<double> u;
  std::vector<double> reaction_all;
  bool linear;
  const StaticAnalysis* this_analysis = nullptr; ///< handed to the writer

  Impl(const Model& m, AnalysisOptions o, ResultWriter* w)
      : model(m), options(o), writer(w), dim(spatial_dim(m.kinematics)),
        dofs(m.mesh.num_nodes(), dim), dist(m.mesh.num_nodes(), dim),
        cell_owned(owned_cell_flags(m.mesh, dist)),
        solid(m.mesh, m.kinematics, dofs, m.material_of_region, indices_of(cell_owned)),
        loads(m.mesh, m.kinematics, dofs, cell_owned), R(dist), du(dist), F_prev(dist),
        F_cur(dist), F_step(dist), reaction(dist),
        solver(LinearSolverOptions::from_parameters(m.spec.linear_solver)),
        u(dofs.num_dofs(), 0.0), linear(all_linear(m)) {
    SparsityPattern pattern;
    solid.add_to_pattern(pattern);
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
    if (!m.spec.initial_stress.empty())
      solid.set_initial_stress(initial_stress_function(m));
    F_prev.set_zero();
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
      case LoadSpec::Type::Pressure: loads.add_pressure(ld.set, ld.pressure, F); break;
      case LoadSpec::Type::Traction: loads.add_traction(ld.set, ld.traction, F); break;
      case LoadSpec::Type::Gravity: loads.add_gravity(model.material_of_region, F); break;
      }
    }
    F.finish_assembly();
  }

  RunSummary run(const std::function<void(const StepReport&)>& on_step);
};

RunSummary StaticAnalysis::Impl::run(const std::function<void(const StepReport&)>& on_step) {
  const auto run_start = std::chrono::steady_clock::now();
  RunSummary summary;
  summary.num_dofs = dofs.num_dofs();
  double time = 0.0;
  const Index first = dist.first_owned_dof(), n_owned = dist.num_owned_dofs();

  for (std::size_t s = 0; s < model.spec.stages.size(); ++s) {
    const StageSpec& stage = model.spec.stages[s];
    std::map<Index, double> target;
    for (const auto& bc : stage.boundary_conditions)
      for (Index node : set_nodes(bc.set)) target[dofs.dof(node, bc.component)] = bc.value;
    std::map<Index, double> start;
    for (const auto& [d, v] : target) start[d] = u[d];
    assemble_loads(stage, F_cur);
    bool matrix_ready = false; // the constrained set changed: the tangent must be rebuilt

    for (int k = 1; k <= stage.increments; ++k) {
      const auto step_start = std::chrono::steady_clock::now();
      const double lambda = static_cast<double>(k) / stage.increments;
      // F(λ) = F_prev + λ (F_cur − F_prev), owned entries only.
      F_step.copy(F_prev);
      F_step.scale(1.0 - lambda);
      F_step.axpy(lambda, F_cur);

      Constraints constraints;
      double reference = 0.0, norm = 0.0;
      std::vector<double> history;
      int it = 0, linear_iterations = 0;
      bool converged = false;
      for (;; ++it) {
        constraints.clear();
        for (const auto& [d, v] : target)
          constraints.set(d, it == 0 ? start[d] + lambda * (v - start[d]) - u[d] : 0.0);
        const bool need_matrix = !(linear && matrix_ready);
        auto t0 = std::chrono::steady_clock::now();
        R.set_zero();
        if (need_matrix) K->set_zero();
        solid.assemble(u, constraints, need_matrix ? K.get() : nullptr, R);
        R.finish_assembly();
        if (need_matrix) K->finish_assembly();
        double* r = R.owned_values();
        const double* f = F_step.owned_values();
        for (Index i = 0; i < n_owned; ++i)
          if (!constraints.is_constrained(first + i)) r[i] += f[i];
        norm = R.norm2();
        summary.assembly_seconds += seconds_since(t0);
        if (it == 0) {
          reference = std::max(norm, F_step.norm2());
          if (reference == 0.0) {
            converged = true;
            break;
          }
        }
        history.push_back(norm / reference);
        if (it > 0 && norm <= options.residual_tolerance * reference) {
          converged = true;
          break;
        }
        if (it >= options.max_iterations) break;
        if (need_matrix) {
          t0 = std::chrono::steady_clock::now();
          solver.setup(*K);
          summary.setup_seconds += seconds_since(t0);
          matrix_ready = true;
          ++summary.matrix_setups;
        }
        du.set_zero();
        t0 = std::chrono::steady_clock::now();
        const LinearSolveStats stats = solver.solve(R, du);
        summary.solve_seconds += seconds_since(t0);
        linear_iterations += stats.iterations;
        summary.linear_iterations += stats.iterations;
        ++summary.linear_solves;
        const std::vector<double> du_all = du.gather_all();
        for (std::size_t i = 0; i < u.size(); ++i) u[i] += du_all[i];
      }
      if (!converged) {
        std::ostringstream msg;
        msg << "stage '" << stage.name << "' (" << s + 1 << "), step " << k << "/"
            << stage.increments << ": Newton did not converge in " << it
            << " iterations; relative residual history:";
        for (double h : history) msg << " " << h;
        msg << " (tolerance " << options.residual_tolerance << ")";
        throw SolverError(msg.str());
      }
      solid.commit();
      // Reactions: f_int − f_ext on every DOF (nonzero only where supports act).
      auto t0 = std::chrono::steady_clock::now();
      reaction.set_zero();
      solid.internal_force(u, reaction);
      reaction.finish_assembly();
      reaction.axpy(-1.0, F_step);
      reaction_all = reaction.gather_all();
      summary.assembly_seconds += seconds_since(t0);

      StepReport rep;
      rep.stage = stage.name;
      rep.stage_index = static_cast<int>(s);
      rep.step = k;
      rep.steps = stage.increments;
      rep.global_step = ++summary.steps;
      rep.time = time + lambda * stage.duration;
      rep.load_factor = lambda;
      rep.iterations = it;
      rep.linear_iterations = linear_iterations;
      rep.residual = history.empty() ? 0.0 : history.back();
      rep.seconds = seconds_since(step_start);
      t0 = std::chrono::steady_clock::now();
      if (writer) writer->write_step(rep, *this_analysis);
      summary.output_seconds += seconds_since(t0);
      if (on_step) on_step(rep);
    }
    F_prev.copy(F_cur);
    time += stage.duration;
    if (stage.reset_displacements) {
      solid.absorb_stress_into_initial(u);
      std::fill(u.begin(), u.end(), 0.0);
    }
  }
  summary.seconds = seconds_since(run_start);
  return summary;
}

StaticAnalysis::StaticAnalysis(const Model& model, AnalysisOptions options, ResultWriter* writer)
    : impl_(std::make_unique<Impl>(model, options, writer)) {
  impl_->this_analysis = this;
}

StaticAnalysis::~StaticAnalysis() = default;

RunSummary StaticAnalysis::run(const std::function<void(const StepReport&)>& on_step) {
  return impl_->run(on_step);
}

const std::vector<double>& StaticAnalysis::displacement() const { return impl_->u; }
const DofMap& StaticAnalysis::dofs() const { return impl_->dofs; }

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
