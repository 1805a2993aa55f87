#pragma once
/// Writes the results of every converged increment: a VTK time series of the bulk
/// (displacement, strain, stress, owning rank; the writer adds the region id) and a CSV of reaction forces per
/// supported set. Files are complete after each step, so an interrupted run keeps every
/// converged increment readable.

#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"

#include <memory>
#include <string>
#include <vector>

namespace bipot {

class VtkSeriesWriter;
class CsvWriter;

class ResultWriter {
public:
  ResultWriter(const Model& model, int rank, int size);
  ~ResultWriter();

  /// Called by StaticAnalysis on every rank after each converged increment (collective).
  void write_step(const StepReport& report, const StaticAnalysis& analysis);

  const std::string& directory() const { return directory_; }
  /// Path of the reactions CSV.
  std::string reactions_path() const;
  /// Path of the bulk .pvd series.
  std::string pvd_path() const;

private:
  const Model& model_;
  std::string directory_;
  int rank_;
  std::vector<std::string> reaction_sets_;
  std::unique_ptr<VtkSeriesWriter> vtk_;
  std::unique_ptr<CsvWriter> reactions_;
};

} // namespace bipot
