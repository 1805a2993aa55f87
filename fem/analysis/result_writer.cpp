#include "fem/analysis/result_writer.hpp"

#include "fem/io/csv_writer.hpp"
#include "fem/io/vtk_writer.hpp"
#include "fem/linalg/communicator.hpp"

#include <filesystem>
#include <map>
#include <set>

namespace bipot {

namespace {
std::vector<std::string> component_names(const Model& model) {
  if (model.kinematics == Kinematics::Axisymmetric) return {"r", "z"};
  if (model.kinematics == Kinematics::PlaneStrain) return {"x", "y"};
  return {"x", "y", "z"};
}
// How each step was reached, last in every CSV row: the same flags as the progress lines.
const std::vector<std::string> flag_columns = {"cutbacks", "staggered", "unstable", "traced"};
void add_flags(const StepReport& r, std::vector<double>& row) {
  row.insert(row.end(), {static_cast<double>(r.cutbacks), static_cast<double>(r.staggered),
                         r.unstable ? 1.0 : 0.0, r.traced ? 1.0 : 0.0});
}

// rigid_bodies.csv: per body, its reference node's displacements and rotations, then what
// it transmits to the body (forces, moments about the reference point).
std::unique_ptr<CsvWriter> rigid_body_csv(const Model& model, const std::string& directory) {
  std::vector<std::string> motion = {"ux", "uy", "rz"}, force = {"fx", "fy", "mz"};
  if (model.kinematics == Kinematics::Axisymmetric)
    motion = {"ur", "uz"}, force = {"fr", "fz"};
  else if (model.kinematics == Kinematics::ThreeD)
    motion = {"ux", "uy", "uz", "rx", "ry", "rz"}, force = {"fx", "fy", "fz", "mx", "my", "mz"};
  std::vector<std::string> cols = {"stage", "step", "time", "load_factor"};
  for (const RigidBody& b : model.rigid_bodies) {
    for (const auto& c : motion)
      cols.push_back(b.name + "_" + c);
    for (const auto& c : force)
      cols.push_back(b.name + "_" + c);
  }
  cols.insert(cols.end(), flag_columns.begin(), flag_columns.end());
  return std::make_unique<CsvWriter>(directory + "/rigid_bodies.csv", cols);
}

} // namespace

ResultWriter::ResultWriter(const Model& model, int rank, int size, std::string directory)
    : model_(model),
      directory_(directory.empty() ? model.spec.output.directory : std::move(directory)),
      rank_(rank) {
  std::filesystem::create_directories(directory_);
  // Only the (set, component) pairs some stage constrains: the other components of a set's
  // reaction are zero to the solver tolerance (the set is free that way): only noise.
  std::set<std::pair<std::string, int>> constrained;
  for (const auto& stage : model.spec.stages)
    for (const auto& bc : stage.boundary_conditions)
      constrained.insert({bc.set, bc.component});
  for (const auto& [set, component] : constrained) {
    if (reaction_sets_.empty() || reaction_sets_.back() != set) reaction_sets_.push_back(set);
    reaction_columns_.push_back({reaction_sets_.size() - 1, component});
  }
  if (model.spec.output.vtk)
    vtk_ = std::make_unique<VtkSeriesWriter>(directory_, "solution", rank, size);
  if (rank == 0) {
    for (std::size_t k = 0; k < model.interfaces.size(); ++k) {
      // Tied interfaces get their tractions from body 1's forces (StaticAnalysis), which
      // needs body 1 as a region: not for tied facet-set interfaces (but tied obstacles:
      // the reactions of the nodes they hold).
      if (shares_nodes(model.interfaces[k]) && model.spec.interfaces[k].between.size() != 2 &&
          !model.interfaces[k].obstacle)
        continue;
      const auto& iface = model.interfaces[k];
      written_.push_back(k);
      // The interface mesh: one node per pair (at node a), the body-1 facets as cells.
      Mesh m;
      m.dim = model.mesh.dim;
      std::map<Index, Index> pair_of_node;
      for (const auto& p : iface.pairs) {
        pair_of_node[p.node_a] = static_cast<Index>(m.nodes.size());
        m.nodes.push_back(model.mesh.nodes[p.node_a]);
      }
      const int region = m.region_id(iface.name);
      for (const auto& f : iface.facets_a) {
        std::vector<Index> ids;
        for (Index n : f.nodes)
          ids.push_back(pair_of_node.at(n));
        m.add_cell(f.type, ids, region);
      }
      interface_meshes_.push_back(std::move(m));
      // Like the solution series, only with `output.vtk` and at the `every` steps; the CSV
      // below takes every step.
      interface_vtk_.push_back(
          model.spec.output.vtk
              ? std::make_unique<VtkSeriesWriter>(directory_, "interface_" + iface.name, 0, 1)
              : nullptr);
      std::vector<std::string> cols = {"stage", "step", "time", "load_factor"};
      for (const auto& c : component_names(model))
        cols.push_back("force_" + c);
      cols.insert(cols.end(), flag_columns.begin(), flag_columns.end());
      interface_csv_.push_back(
          std::make_unique<CsvWriter>(directory_ + "/interface_" + iface.name + ".csv", cols));
    }
    std::vector<std::string> columns = {"stage", "step", "time", "load_factor"};
    const auto names = component_names(model);
    for (const auto& [set, component] : reaction_columns_)
      columns.push_back(reaction_sets_[set] + "_f" + names.at(component));
    columns.insert(columns.end(), flag_columns.begin(), flag_columns.end());
    reactions_ = std::make_unique<CsvWriter>(reactions_path(), columns);
    energy_ = std::make_unique<CsvWriter>(
        directory_ + "/energy.csv",
        std::vector<std::string>{"stage", "step", "time", "load_factor", "external_work",
                                 "interference_work", "bulk_energy", "interface_energy",
                                 "adhesion_dissipation", "viscous_dissipation", "contact_work",
                                 "balance_error", "relative_error", "energy_halvings",
                                 "over_energy_budget"});
    if (!model.rigid_bodies.empty()) rigid_bodies_ = rigid_body_csv(model, directory_);
  }
}

ResultWriter::~ResultWriter() = default;

std::string ResultWriter::reactions_path() const {
  return directory_ + "/reactions.csv";
}
std::string ResultWriter::pvd_path() const {
  return directory_ + "/solution.pvd";
}

void ResultWriter::resume(const std::string& directory, std::size_t stages_done, double time,
                          int next_stage_steps) {
  const auto last = static_cast<double>(stages_done);
  const auto file_name = [](const std::string& path) {
    return path.substr(path.find_last_of('/') + 1);
  };
  const auto copy = [&](CsvWriter* csv) {
    if (csv) csv->copy_rows(directory + "/" + file_name(csv->path()), last, next_stage_steps);
  };
  copy(reactions_.get());
  for (const auto& csv : interface_csv_)
    copy(csv.get());
  copy(energy_.get());
  copy(rigid_bodies_.get());
  if (vtk_) vtk_->resume(directory, time);
  for (const auto& vtk : interface_vtk_)
    if (vtk) vtk->resume(directory, time);
}

void ResultWriter::write_step(const StepReport& report, const StaticAnalysis& analysis) {
  std::vector<double> row = {static_cast<double>(report.stage_index + 1),
                             static_cast<double>(report.step), report.time, report.load_factor};
  std::vector<std::vector<double>> reactions;
  for (const auto& s : reaction_sets_)
    reactions.push_back(analysis.reaction(s));
  for (const auto& [set, component] : reaction_columns_)
    row.push_back(reactions[set].at(component));
  add_flags(report, row);
  if (reactions_) reactions_->write_row(row);
  if (energy_) {
    const EnergyTotals& e = report.energy;
    energy_->write_row(
        {static_cast<double>(report.stage_index + 1), static_cast<double>(report.step), report.time,
         report.load_factor, e.external_work, e.interference_work, e.bulk_energy,
         e.interface_energy, e.adhesion_dissipation, e.viscous_dissipation, e.contact_work,
         e.balance_error(), e.relative_error(), static_cast<double>(report.energy_halvings),
         report.over_energy_budget ? 1.0 : 0.0});
  }
  if (rigid_bodies_) {
    row.resize(4);
    for (std::size_t b = 0; b < model_.rigid_bodies.size(); ++b)
      for (double v : analysis.rigid_body_state(b))
        row.push_back(v);
    add_flags(report, row);
    rigid_bodies_->write_row(row);
  }
  // `every` counts the plan (and the traced steps), not the sub-increments: halvings, by
  // cut-backs or by energy_tolerance (thousands on a viscous pile at 1e-6), would otherwise
  // multiply the VTK series. The CSVs keep every increment.
  const int every = model_.spec.output.every;
  const bool due = report.stage_end || report.requested_output ||
                   (report.planned_step > 0 ? report.planned_step % every == 0
                                            : report.traced && report.step % every == 0);
  if (rank_ == 0) write_interfaces(report, analysis, due);
  if (!vtk_ || !due) return;
  std::vector<Index> cells;
  std::vector<double> strain, stress;
  analysis.cell_results(cells, strain, stress);
  const int dim = spatial_dim(model_.kinematics);
  const int nv = voigt_size(dim);
  Field displacement{"displacement", dim, {}, &analysis.displacement()};
  // Moved in, not listed in braces: an initializer list copies every array.
  std::vector<Field> cell_fields;
  cell_fields.push_back(Field{"strain", nv, std::move(strain)});
  cell_fields.push_back(Field{"stress", nv, std::move(stress)});
  cell_fields.push_back(Field{"rank", 1, std::vector<double>(cells.size(), rank_)});
  // The materials' own fields (equivalent plastic strain, yield indicator, ...), cell averages.
  const std::vector<std::string> names = analysis.output_field_names();
  const std::vector<double> values = analysis.cell_output_fields();
  for (std::size_t f = 0; f < names.size(); ++f) {
    Field field{names[f], 1, std::vector<double>(cells.size())};
    for (std::size_t k = 0; k < cells.size(); ++k)
      field.values[k] = values[k * names.size() + f];
    cell_fields.push_back(std::move(field));
  }
  vtk_->write_step(report.time, model_.mesh, cells, {displacement}, cell_fields);
  barrier();
}

void ResultWriter::write_interfaces(const StepReport& report, const StaticAnalysis& analysis,
                                    bool vtk_due) {
  const int dim = spatial_dim(model_.kinematics);
  for (std::size_t k = 0; k < interface_csv_.size(); ++k) {
    const auto& ia = *analysis.interfaces()[written_[k]];
    std::vector<double> row = {static_cast<double>(report.stage_index + 1),
                               static_cast<double>(report.step), report.time, report.load_factor};
    const auto f = ia.resultant();
    for (int c = 0; c < dim; ++c)
      row.push_back(f[c]);
    add_flags(report, row);
    interface_csv_[k]->write_row(row);
    if (!interface_vtk_[k] || !vtk_due) continue;

    const auto& results = ia.results();
    const std::size_t n = results.size();
    Field tn{"normal_traction", 1, {}}, tt{"tangential_traction", dim - 1, {}},
        p{"contact_pressure", 1, {}}, gn{"opening", 1, {}}, gt{"slip", dim - 1, {}},
        beta{"beta", 1, {}}, status{"status", 1, {}};
    for (std::size_t i = 0; i < n; ++i) {
      const auto& r = results[i];
      tn.values.push_back(r.traction(0));
      p.values.push_back(r.r(0));
      gn.values.push_back(r.jump(0));
      for (int c = 1; c < dim; ++c) {
        tt.values.push_back(r.traction(c));
        gt.values.push_back(r.jump(c));
      }
      beta.values.push_back(r.beta);
      // 0 open, 1 stick, 2 slip, 3 bonded (β > 0)
      status.values.push_back(static_cast<double>(reported_status(r)));
    }
    std::vector<Index> cells(interface_meshes_[k].num_cells());
    for (Index c = 0; c < interface_meshes_[k].num_cells(); ++c)
      cells[c] = c;
    interface_vtk_[k]->write_step(report.time, interface_meshes_[k], cells,
                                  {tn, tt, p, gn, gt, beta, status}, {});
  }
}

} // namespace bipot
