#include "fem/analysis/result_writer.hpp"

#include "fem/io/csv_writer.hpp"
#include "fem/io/vtk_writer.hpp"
#include "fem/linalg/communicator.hpp"

#include <filesystem>
#include <set>

namespace bipot {

namespace {
std::vector<std::string> component_names(const Model& model) {
  if (model.kinematics == Kinematics::Axisymmetric) return {"r", "z"};
  if (model.kinematics == Kinematics::PlaneStrain) return {"x", "y"};
  return {"x", "y", "z"};
}
} // namespace

ResultWriter::ResultWriter(const Model& model, int rank, int size)
    : model_(model), directory_(model.spec.output.directory), rank_(rank) {
  std::filesystem::create_directories(directory_);
  std::set<std::string> sets;
  for (const auto& stage : model.spec.stages)
    for (const auto& bc : stage.boundary_conditions) sets.insert(bc.set);
  reaction_sets_.assign(sets.begin(), sets.end());
  if (model.spec.output.vtk)
    vtk_ = std::make_unique<VtkSeriesWriter>(directory_, "solution", rank, size);
  if (rank == 0) {
    std::vector<std::string> columns = {"stage", "step", "time", "load_factor"};
    for (const auto& s : reaction_sets_)
      for (const auto& c : component_names(model)) columns.push_back(s + "_f" + c);
    reactions_ = std::make_unique<CsvWriter>(reactions_path(), columns);
  }
}

ResultWriter::~ResultWriter() = default;

std::string ResultWriter::reactions_path() const { return directory_ + "/reactions.csv"; }
std::string ResultWriter::pvd_path() const { return directory_ + "/solution.pvd"; }

void ResultWriter::write_step(const StepReport& report, const StaticAnalysis& analysis) {
  std::vector<double> row = {static_cast<double>(report.stage_index + 1),
                             static_cast<double>(report.step), report.time, report.load_factor};
  for (const auto& s : reaction_sets_)
    for (double f : analysis.reaction(s)) row.push_back(f);
  if (reactions_) reactions_->write_row(row);

  const bool due = report.global_step % model_.spec.output.every == 0 || report.step == report.steps;
  if (!vtk_ || !due) return;
  std::vector<Index> cells;
  std::vector<double> strain, stress;
  analysis.cell_results(cells, strain, stress);
  const int dim = spatial_dim(model_.kinematics);
  const int nv = voigt_size(dim);
  Field displacement{"displacement", dim, analysis.displacement()};
  Field owner{"rank", 1, std::vector<double>(cells.size(), rank_)};
  vtk_->write_step(report.time, model_.mesh, cells, {displacement},
                   {Field{"strain", nv, strain}, Field{"stress", nv, stress}, owner});
  barrier();
}

} // namespace bipot
