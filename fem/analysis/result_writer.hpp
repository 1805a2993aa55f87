#pragma once
/// Writes the results of every converged increment: a VTK time series of the bulk
/// (displacement, strain, stress, owning rank; the writer adds the region id), a CSV of
/// reaction forces per supported set and constrained component, and per interface a VTK series of
/// its line/surface mesh (tractions, contact pressure, opening, slip, β, status) and a CSV of the
/// resultant force body 1 exerts on body 2. Files are complete after each step, so an interrupted
/// run keeps every converged increment readable.

#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace bipot {

class VtkSeriesWriter;
class CsvWriter;

class ResultWriter {
public:
  /// Writes into `directory` (created if missing); empty: the model's output.directory.
  ResultWriter(const Model& model, int rank, int size, std::string directory = "");
  ~ResultWriter();

  /// Called by StaticAnalysis on every rank after each converged increment (collective).
  void write_step(const StepReport& report, const StaticAnalysis& analysis);

  /// A restart: the results of an earlier run in `directory` (the folder its checkpoint is
  /// in) up to the end of stage `stages_done` and `next_stage_steps` increments into the next
  /// (a checkpoint within it), ending at pseudo-time `time`, are copied first — the CSV rows
  /// and the VTK steps — so that this run's folder holds the whole series. Every rank, before
  /// the first write_step(). Throws bipot::Error if they cannot be read.
  void resume(const std::string& directory, std::size_t stages_done, double time,
              int next_stage_steps = 0);

  const std::string& directory() const { return directory_; }
  /// Path of the reactions CSV.
  std::string reactions_path() const;
  /// Path of the bulk .pvd series.
  std::string pvd_path() const;

private:
  /// The interface CSV rows, and with `vtk_due` their VTK series step.
  void write_interfaces(const StepReport& report, const StaticAnalysis& analysis, bool vtk_due);

  const Model& model_;
  std::string directory_;
  int rank_;
  std::vector<std::string> reaction_sets_; ///< sets with a displacement condition, sorted
  /// The reactions.csv columns: (index into reaction_sets_, component), in the order of the
  /// sets, then of the components; only the components some stage constrains.
  std::vector<std::pair<std::size_t, int>> reaction_columns_;
  std::unique_ptr<VtkSeriesWriter> vtk_;
  std::unique_ptr<CsvWriter> reactions_;
  std::unique_ptr<CsvWriter> energy_;       ///< energy.csv (rank 0)
  std::unique_ptr<CsvWriter> rigid_bodies_; ///< rigid_bodies.csv, when the model has any
  // Per interface (rank 0): its line/surface mesh (nodes = pairs), VTK series and CSV.
  std::vector<Mesh> interface_meshes_;
  std::vector<std::unique_ptr<VtkSeriesWriter>> interface_vtk_;
  std::vector<std::unique_ptr<CsvWriter>> interface_csv_;
  std::vector<std::size_t> written_; ///< model interface index of each written interface
};

} // namespace bipot
