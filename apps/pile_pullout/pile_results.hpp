#pragma once
/// What the pile app writes besides the toolkit's VTK series: the head force–displacement
/// curve (head_force.csv) and shaft profiles (profiles.csv) at chosen head displacements.
/// Rows are flushed as they are written, so an interrupted run keeps every converged step.

#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/core/state_arrays.hpp"

#include <fstream>
#include <string>
#include <vector>

namespace bipot::pile {

/// Head displacement (m, upward, mean over the head nodes) and head force (kN, upward pull =
/// the vertical reaction of the head nodes, whole circumference).
struct HeadState {
  double displacement = 0;
  double force = 0;
};

HeadState head_state(const Model& model, const StaticAnalysis& analysis);

class PileResults {
public:
  /// Opens the CSV files in `directory` (rank 0 only writes; other ranks keep no files).
  /// `profiles_at_mm`: head displacements at which the shaft profiles are written.
  PileResults(const Model& model, const std::string& directory, std::vector<double> profiles_at_mm,
              bool write);

  /// Called after every converged increment.
  void record(const StepReport& report, const StaticAnalysis& analysis);

  /// What the curve and profiles need to continue after a restart (the next profile due, the
  /// peak so far, the last head state), saved with each checkpoint as "app.pile_results".
  StateArrays save_state() const;
  /// A restart from a checkpoint in folder `from` written after `steps` increments: copies
  /// the rows of its head_force.csv and profiles.csv up to there and restores save_state()'s
  /// values from `state`. Every rank, before the run. Throws bipot::Error if the files cannot
  /// be read or the state lacks the pile's values (a checkpoint of bipot, not pile_pullout).
  void resume(const std::string& from, int steps, const StateArrays& state);

  std::string head_force_path() const { return directory_ + "/head_force.csv"; }
  std::string profiles_path() const { return directory_ + "/profiles.csv"; }
  /// Largest pull-out force so far and the head displacement where it occurred.
  double peak_force() const { return peak_force_; }
  double peak_displacement() const { return peak_displacement_; }
  HeadState last() const { return last_; }

private:
  void write_profile(const StepReport& report, const StaticAnalysis& analysis, double head_mm);

  const Model& model_;
  std::string directory_;
  std::vector<double> profiles_at_mm_;
  std::size_t next_profile_ = 0;
  bool write_;
  std::ofstream head_, profiles_;
  double peak_force_ = 0, peak_displacement_ = 0;
  HeadState last_;
};

} // namespace bipot::pile
