#pragma once
/// What the apps do for `output.checkpoint` and `run --restart FILE` (docs/input_reference.md,
/// "Checkpoints and restart"): checkpoints are written into the results folder at stage ends
/// and at chosen planned steps within stages; a restart continues from where its checkpoint
/// was written, and its results folder starts with the earlier run's results up to there,
/// copied from the checkpoint's folder.

#include "fem/analysis/model.hpp"
#include "fem/analysis/result_writer.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/core/state_arrays.hpp"

#include <functional>
#include <string>

namespace bipot::app {

/// An app's own state saved with each checkpoint (what its own outputs need to continue),
/// under names starting with "app."; the analysis ignores them.
using AppState = std::function<StateArrays()>;

/// `checkpoint_<stage>.bin` and `checkpoint_<stage>_step<k>.bin`.
std::string checkpoint_name(const std::string& stage);
std::string step_checkpoint_name(const std::string& stage, int k);

/// AnalysisOptions::on_stage_end writing `<folder>/checkpoint_<stage>.bin` at the end of the
/// stages output.checkpoint.after names (collective: every rank gathers, rank 0 writes).
/// `*analysis` must point to the running analysis when a stage ends.
std::function<void(std::size_t, double)> checkpoint_writer(const Model& model,
                                                           const StaticAnalysis* const* analysis,
                                                           std::string folder, AppState app = {});

/// AnalysisOptions::on_increment_end writing `<folder>/checkpoint_<stage>_step<k>.bin` when
/// an increment ends on the planned level k of a stage that output.checkpoint's `steps` or
/// `every` asks for (collective).
std::function<void(const StepReport&)> step_checkpoint_writer(const Model& model,
                                                              const StaticAnalysis* const* analysis,
                                                              std::string folder,
                                                              AppState app = {});

/// Reads a checkpoint to restart `model` from (every rank), refusing one of another input or
/// version (InputError naming the file and the reason).
StateArrays read_restart(const std::string& file, const Model& model);

/// Where a restart continues.
struct RestartPoint {
  std::size_t stages_done = 0; ///< stages complete
  int stage_steps = 0;         ///< increments done in the next stage (a checkpoint within it)
  int global_steps = 0;        ///< converged increments of the run so far
  std::string text;            ///< "after stage 'a'" or "at step 3 of stage 'b' (load 3/8)"
  std::string folder;          ///< the checkpoint's folder (the earlier results)
};

/// Restores `state` (read from `file`) into `analysis` and copies the earlier results from the
/// folder of `file` into `writer`'s: CSV rows and VTK steps up to the checkpoint, and the
/// checkpoints written up to there. Every rank, before run().
RestartPoint restore(const std::string& file, const StateArrays& state, StaticAnalysis& analysis,
                     ResultWriter& writer, const Model& model);

} // namespace bipot::app
